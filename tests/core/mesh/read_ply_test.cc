// PLY meshes: ascii, binary little and big endian, extra properties and
// elements skipped; ReadPlyMesh, ParsePlyHeader and ReadPlyData.
#include <limits>
#include <ostream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing_files::AppendRaw;
using testing_files::Message;
using testing_files::WriteTemp;

constexpr double kSquare[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

// The unit square as triangles (0 1 2) and (0 2 3), with extra vertex and
// face properties and an extra "edge" element.
std::string AsciiSquare() {
  return "ply\nformat ascii 1.0\ncomment made by a test\nobj_info none\n"
         "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "property float confidence\nproperty uchar intensity\n"
         "element face 2\nproperty list uchar int vertex_indices\nproperty uchar flags\n"
         "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
         "end_header\n"
         "0 0 0 0.5 1\n1 0 0 0.5 1\n1 1 0 0.5 1\n0 1 0 0.5 1\n"
         "3 0 1 2 7\n3 0 2 3 7\n0 1\n";
}

// The same square in binary: xyz as `double_xyz` ? double : float, an extra
// uchar colour per vertex, an int32-counted index list, and a trailing
// "material" element with a list property to skip.
std::string BinarySquare(bool big_endian, bool double_xyz) {
  std::string out = std::string("ply\nformat ") +
                    (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\n";
  const char* type = double_xyz ? "double" : "float";
  for (const char* axis : {"x", "y", "z"}) out += std::string("property ") + type + " " + axis + "\n";
  out += "property uchar red\nelement face 2\nproperty list int int vertex_index\n"
         "element material 1\nproperty list uchar float weights\nend_header\n";
  for (const auto& p : kSquare) {
    for (double c : p) {
      if (double_xyz) {
        AppendRaw<double>(out, c, big_endian);
      } else {
        AppendRaw<float>(out, static_cast<float>(c), big_endian);
      }
    }
    AppendRaw<uint8_t>(out, 200);
  }
  for (const auto& f : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
    AppendRaw<int32_t>(out, 3, big_endian);
    for (int i : f) AppendRaw<int32_t>(out, i, big_endian);
  }
  AppendRaw<uint8_t>(out, 2);
  AppendRaw<float>(out, 0.5f, big_endian);
  AppendRaw<float>(out, 0.5f, big_endian);
  return out;
}

void ExpectSquare(const absl::StatusOr<Mesh>& mesh) {
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->tri.n_vertices(), 4u);
  EXPECT_EQ(mesh->tri.n_faces(), 2u);
  EXPECT_THAT(mesh->face_of_input, ElementsAre(0, 1));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(ToEigen(mesh->tri.point(TriMesh::VertexHandle(i))),
              Eigen::Vector3d(kSquare[i][0], kSquare[i][1], kSquare[i][2]));
  }
  EXPECT_EQ(MeshStatistics(*mesh).boundary_edge_count, 4);
}

TEST(ReadPly, ReadsAsciiSkippingOtherPropertiesAndElements) {
  ExpectSquare(ReadMesh(WriteTemp("square_ascii.ply", AsciiSquare())));
}

TEST(ReadPly, ReadsBinaryLittleEndianFloat) {
  ExpectSquare(ReadMesh(WriteTemp("square_le.ply", BinarySquare(false, false))));
}

TEST(ReadPly, ReadsBinaryBigEndianDouble) {
  ExpectSquare(ReadMesh(WriteTemp("square_be.ply", BinarySquare(true, true))));
}

TEST(ReadPly, ReadsCrLfHeader) {
  std::string text = AsciiSquare();
  for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 2)) {
    text.replace(at, 1, "\r\n");
  }
  ExpectSquare(ReadMesh(WriteTemp("crlf.ply", text)));
}

TEST(ReadPly, RejectsTruncatedBinaryWithByteOffset) {
  std::string bytes = BinarySquare(false, false);
  bytes.resize(bytes.size() - 12);  // into the second face
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("truncated_binary.ply", bytes));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr("\"truncated_binary.ply\""));
  EXPECT_THAT(Message(mesh.status()), HasSubstr("truncated at byte offset"));
}

TEST(ReadPly, RejectsHugeDeclaredCountBeforeAllocating) {
  std::string bytes = BinarySquare(false, false);
  bytes.replace(bytes.find("vertex 4"), 8, "vertex 150000000");
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("huge_count.ply", bytes));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr("huge_count.ply"));
  EXPECT_THAT(Message(mesh.status()),
              HasSubstr("header declares 150000000 \"vertex\" elements (at least 13 bytes each)"));
}

struct BadPly {
  const char* file;
  std::string text;
  const char* message;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the file keeps the names
// the same from build to build.
void PrintTo(const BadPly& c, std::ostream* os) { *os << c.file; }

class ReadPlyRejects : public testing::TestWithParam<BadPly> {};

TEST_P(ReadPlyRejects, WithFileNameAndPlace) {
  const BadPly& bad = GetParam();
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp(bad.file, bad.text));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr(std::string("\"") + bad.file + "\""));
  EXPECT_THAT(Message(mesh.status()), HasSubstr(bad.message));
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

INSTANTIATE_TEST_SUITE_P(
    FaultyFiles, ReadPlyRejects,
    testing::Values(
        BadPly{"nan_vertex.ply", Replace(AsciiSquare(), "1 1 0 0.5", "1 nan 0 0.5"),
               "line 20: vertex 2: non-finite coordinate"},
        BadPly{"out_of_range.ply", Replace(AsciiSquare(), "3 0 2 3 7", "3 0 2 4 7"),
               "line 23: face 1: vertex index 4 out of range [0, 4)"},
        BadPly{"two_corner_face.ply", Replace(AsciiSquare(), "3 0 2 3 7", "2 0 2 7"),
               "line 23: face 1 has 2 corners"},
        BadPly{"missing_value.ply", Replace(AsciiSquare(), "1 0 0 0.5 1", "1 0 0 0.5"),
               "line 19: expected a number for intensity"},
        BadPly{"no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 0\n",
               "no \"end_header\" line"},
        BadPly{"bad_format.ply", Replace(AsciiSquare(), "ascii", "utf8"),
               "header line 2: unknown format \"utf8\""},
        BadPly{"missing_x.ply", Replace(AsciiSquare(), "property float x", "property float u"),
               "element vertex has no scalar property x"},
        BadPly{"bad_type.ply", Replace(AsciiSquare(), "property float y", "property real y"),
               "header line 7: unknown type \"real\""},
        BadPly{"no_faces.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n",
               "no faces (a point cloud, not a mesh)"}),
    [](const testing::TestParamInfo<BadPly>& info) {
      std::string name = info.param.file;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace meshseg
