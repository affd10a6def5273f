#include "mesh/ply_body.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"

#include "temp_file.h"

namespace meshseg::mesh_internal {
namespace {

const Source kSrc{"read_point_cloud", "b.ply"};

TEST(ReadPlyData, ReadsNormalsOnlyWhenAllThreeArePresent) {
  const std::string with =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
      "property double z\nproperty double nz\nproperty double ny\nproperty double nx\n"
      "end_header\n1 2 3 0.3 0.2 0.1\n";
  absl::StatusOr<PlyData> data = ReadPlyData(with, kSrc, 100);
  ASSERT_TRUE(data.ok()) << data.status();
  ASSERT_EQ(data->normals.size(), 1u);
  EXPECT_EQ(data->normals[0], Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_FALSE(data->has_face_element);

  std::string without = with;
  without.replace(without.find("property double ny\n"), 19, "");
  without.replace(without.find("0.3 0.2 0.1"), 11, "0.3 0.1");
  data = ReadPlyData(without, kSrc, 100);
  ASSERT_TRUE(data.ok()) << data.status();
  EXPECT_TRUE(data->normals.empty());
}

TEST(ReadPlyData, ReadsSignedAndShortBinaryTypes) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty short x\n"
      "property char y\nproperty ushort z\nend_header\n";
  testing_files::AppendRaw<int16_t>(bytes, -300);
  testing_files::AppendRaw<int8_t>(bytes, -7);
  testing_files::AppendRaw<uint16_t>(bytes, 60000);
  const absl::StatusOr<PlyData> data = ReadPlyData(bytes, kSrc, 100);
  ASSERT_TRUE(data.ok()) << data.status();
  EXPECT_EQ(data->vertices[0], Eigen::Vector3d(-300, -7, 60000));
}

TEST(ReadPlyData, RejectsFaceBeforeVertex) {
  const absl::StatusOr<PlyData> data = ReadPlyData(
      "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
      "element vertex 0\nproperty float x\nend_header\n",
      kSrc, 100);
  ASSERT_EQ(data.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(testing_files::Message(data.status()),
              ::testing::HasSubstr("element face comes before element vertex"));
}

TEST(ReadPlyData, RejectsExtraValuesOnAsciiLine) {
  const absl::StatusOr<PlyData> data = ReadPlyData(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3 4\n",
      kSrc, 100);
  ASSERT_EQ(data.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(testing_files::Message(data.status()),
              ::testing::HasSubstr("line 8: extra values after vertex"));
}

// Found by fuzz_ply_ascii (fuzz/regressions/ply_ascii/): a list length too
// large for an integer was converted to one (undefined behaviour) and, for
// an element other than face, trusted as a loop bound.
TEST(ReadPlyData, RejectsListLengthsThatAreNotCountsTheFileCanHold) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement extra 1\nproperty list uchar int values\nend_header\n1 2 3\n";
  for (const char* length : {"3.7e113", "2.5", "nan", "40"}) {
    const absl::StatusOr<PlyData> data = ReadPlyData(head + length + " 1 2 3\n", kSrc, 100);
    ASSERT_EQ(data.status().code(), absl::StatusCode::kInvalidArgument) << length;
    EXPECT_THAT(testing_files::Message(data.status()),
                ::testing::MatchesRegex(".*line 11: list length .* of values is not a whole number of "
                                        "values the [0-9]+ bytes left can hold"))
        << length;
  }
  EXPECT_TRUE(ReadPlyData(head + "3 1 2 3\n", kSrc, 100).ok());

  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty uchar x\nproperty uchar y\n"
      "property uchar z\nelement extra 1\nproperty list uint uchar values\nend_header\n";
  binary += std::string("\1\2\3", 3);
  testing_files::AppendRaw<uint32_t>(binary, 4000000000u);
  const absl::StatusOr<PlyData> data = ReadPlyData(binary, kSrc, 100);
  ASSERT_EQ(data.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(testing_files::Message(data.status()),
              ::testing::HasSubstr("list length 4000000000 of values is not a whole number of "
                                   "values the 0 bytes left can hold"));
}

// A binary body is read in one pass per element; a value that fails a check
// is still reported at its own byte offset, and earlier elements stay read.
TEST(ReadPlyData, NamesTheByteOffsetOfABadBinaryValue) {
  const auto file = [](int32_t third_corner, double z) {
    std::string bytes =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
        "property double y\nproperty double z\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n";
    const std::size_t body = bytes.size();
    for (int v = 0; v < 3; ++v) {
      for (int c = 0; c < 3; ++c) testing_files::AppendRaw<double>(bytes, v == 2 && c == 2 ? z : v);
    }
    for (const int32_t last : {2, third_corner}) {
      testing_files::AppendRaw<uint8_t>(bytes, 3);
      for (const int32_t corner : {0, 1, last}) testing_files::AppendRaw<int32_t>(bytes, corner);
    }
    return std::make_pair(bytes, body);
  };
  const auto [good, body] = file(2, 1.0);
  const absl::StatusOr<PlyData> data = ReadPlyData(good, kSrc, 100);
  ASSERT_TRUE(data.ok()) << data.status();
  EXPECT_EQ(data->vertices[2], Eigen::Vector3d(2, 2, 1));
  EXPECT_EQ(std::vector<int>(data->corners.begin(), data->corners.end()),
            std::vector<int>({0, 1, 2, 0, 1, 2}));

  // The last corner of face 1 (13 bytes per face after 72 of vertices), and
  // the z of vertex 2 (read up to its end).
  const absl::StatusOr<PlyData> bad_index = ReadPlyData(file(3, 1.0).first, kSrc, 100);
  EXPECT_THAT(testing_files::Message(bad_index.status()),
              ::testing::HasSubstr(absl::StrCat("byte offset ", body + 72 + 13 + 13,
                                                ": face 1: vertex index 3 out of range [0, 3)")));
  const absl::StatusOr<PlyData> bad_z =
      ReadPlyData(file(2, std::numeric_limits<double>::infinity()).first, kSrc, 100);
  EXPECT_THAT(testing_files::Message(bad_z.status()),
              ::testing::HasSubstr(absl::StrCat("byte offset ", body + 72,
                                                ": vertex 2: non-finite coordinate inf")));
}

// A mesh of `faces` faces over 7 vertices, triangles except a quad at face
// `quad_at` (-1: none), with index `bad` at the last corner of face
// `bad_at`; binary (either byte order) or ascii, the same values.
std::string Faces(int faces, int quad_at, int bad_at, int32_t bad, const char* format) {
  const bool ascii = std::string(format) == "ascii";
  const bool big = std::string(format) == "binary_big_endian";
  std::string out = absl::StrCat("ply\nformat ", format, " 1.0\nelement vertex 7\n",
                                 "property float x\nproperty float y\nproperty float z\n",
                                 "element face ", faces,
                                 "\nproperty list uchar int vertex_indices\nend_header\n");
  for (int v = 0; v < 7; ++v) {
    for (int c = 0; c < 3; ++c) {
      if (ascii) absl::StrAppend(&out, v + c, c == 2 ? "\n" : " ");
      if (!ascii) testing_files::AppendRaw<float>(out, static_cast<float>(v + c), big);
    }
  }
  for (int f = 0; f < faces; ++f) {
    std::vector<int32_t> corners = {f % 7, (f + 1) % 7, (f + 3) % 7};
    if (f == quad_at) corners.push_back((f + 5) % 7);
    if (f == bad_at) corners.back() = bad;
    if (ascii) absl::StrAppend(&out, corners.size());
    if (!ascii) testing_files::AppendRaw<uint8_t>(out, static_cast<uint8_t>(corners.size()));
    for (const int32_t c : corners) {
      if (ascii) absl::StrAppend(&out, " ", c);
      if (!ascii) testing_files::AppendRaw<int32_t>(out, c, big);
    }
    if (ascii) out += "\n";
  }
  return out;
}

// Binary triangles are read side by side (ReadBinaryTriangles); a face that
// is not a triangle or a bad index sends the element back to the reading
// one value after another. Either way the data, or the error, is the ascii
// reading's (values) and the one-by-one binary reading's (byte offset).
TEST(ReadPlyData, BinaryTrianglesReadSideBySideAsOneByOne) {
  constexpr int kFaces = 50000;  // several blocks of the parallel read
  for (const int quad_at : {-1, 0, 37000, kFaces - 1}) {
    const absl::StatusOr<PlyData> ascii =
        ReadPlyData(Faces(kFaces, quad_at, -1, 0, "ascii"), kSrc, 1 << 20);
    ASSERT_TRUE(ascii.ok()) << ascii.status();
    ASSERT_EQ(ascii->corners.size(), 3u * kFaces + (quad_at >= 0));
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
      const absl::StatusOr<PlyData> binary =
          ReadPlyData(Faces(kFaces, quad_at, -1, 0, format), kSrc, 1 << 20);
      ASSERT_TRUE(binary.ok()) << binary.status();
      EXPECT_TRUE(binary->corners == ascii->corners) << format << " quad at " << quad_at;
      EXPECT_TRUE(binary->face_start == ascii->face_start) << format << " quad at " << quad_at;
      EXPECT_TRUE(binary->vertices == ascii->vertices) << format;
    }
  }
  // 7 vertices of 12 bytes, then 13 bytes a face: a bad last corner of face
  // 41000 is named at the offset after it, as one by one.
  const std::size_t body =
      Faces(kFaces, -1, -1, 0, "binary_little_endian").size() - 7 * 12 - 13 * kFaces;
  for (const int32_t bad : {7, -1}) {
    const absl::StatusOr<PlyData> data =
        ReadPlyData(Faces(kFaces, -1, 41000, bad, "binary_little_endian"), kSrc, 1 << 20);
    EXPECT_THAT(testing_files::Message(data.status()),
                ::testing::HasSubstr(absl::StrCat("byte offset ", body + 7 * 12 + 13 * 41001,
                                                  ": face 41000: vertex index ", bad,
                                                  " out of range [0, 7)")));
  }
}

// Found by fuzz_ply_binary (fuzz/regressions/ply_binary/): a second vertex
// element with a partial set of normals wrote past the first one's normals.
TEST(ReadPlyData, RejectsASecondVertexOrFaceElement) {
  const std::string vertex =
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n";
  const std::string face = "element face 0\nproperty list uchar int vertex_indices\n";
  for (const std::string& elements : {vertex + vertex, vertex + face + face}) {
    const absl::StatusOr<PlyData> data =
        ReadPlyData("ply\nformat ascii 1.0\n" + elements + "end_header\n1 2 3 0 0 1\n1 2 3 0 0 1\n",
                    kSrc, 100);
    ASSERT_EQ(data.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_THAT(testing_files::Message(data.status()),
                ::testing::MatchesRegex(".*element (vertex|face) declared twice"));
  }
}

}  // namespace
}  // namespace meshseg::mesh_internal
