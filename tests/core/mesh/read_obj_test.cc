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
using testing_files::WriteTemp;

// A unit square as one quad with v/vt/vn corners, then a triangle on top of
// it given with negative (relative) indices.
constexpr char kQuadAndTriangle[] =
    "# square and roof\n"
    "mtllib none.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvn 0 0 1\n"
    "g roof\nusemtl a\ns off\n"
    "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
    "v 0.5 2 0\n"
    "f -2//1 -3//1 -1//1\n";

TEST(ReadObj, FanTriangulatesQuadsAndResolvesNegativeIndices) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("quad.obj", kQuadAndTriangle));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->tri.n_vertices(), 5u);
  EXPECT_EQ(mesh->tri.n_faces(), 3u);
  // The quad maps to its first triangle; the roof is the third triangle.
  EXPECT_THAT(mesh->face_of_input, ElementsAre(0, 2));
  std::vector<int> roof;
  for (const auto v : mesh->tri.fv_range(TriMesh::FaceHandle(2))) roof.push_back(v.idx());
  std::sort(roof.begin(), roof.end());
  EXPECT_THAT(roof, ElementsAre(2, 3, 4));
  EXPECT_EQ(MeshStatistics(*mesh).boundary_edge_count, 5);
}

TEST(ReadObj, DetectsObjByContentWithoutExtension) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("no_extension", kQuadAndTriangle));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->tri.n_faces(), 3u);
}

struct BadObj {
  const char* file;
  const char* text;
  const char* message;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the file keeps the names
// the same from build to build.
void PrintTo(const BadObj& c, std::ostream* os) { *os << c.file; }

class ReadObjRejects : public testing::TestWithParam<BadObj> {};

TEST_P(ReadObjRejects, WithFileNameAndLine) {
  const BadObj& bad = GetParam();
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp(bad.file, bad.text));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr(std::string("\"") + bad.file + "\""));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr(bad.message));
}

INSTANTIATE_TEST_SUITE_P(
    FaultyFiles, ReadObjRejects,
    testing::Values(
        BadObj{"nan_vertex.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n",
               "line 2: non-finite coordinate \"nan\""},
        BadObj{"out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
               "line 4: vertex index 4 out of range (3 vertices defined so far)"},
        BadObj{"negative_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
               "line 4: vertex index -4 out of range"},
        BadObj{"zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
               "line 4: vertex index 0 out of range"},
        BadObj{"two_corner_face.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n",
               "line 3: face has 2 corners"},
        BadObj{"bad_number.obj", "v 0 0 0\nv 1 x 0\n", "line 2: expected a coordinate"},
        BadObj{"no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no faces"},
        BadObj{"only_degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n",
               "all 2 faces dropped (2 degenerate"}),
    [](const testing::TestParamInfo<BadObj>& info) {
      std::string name = info.param.file;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace meshseg
