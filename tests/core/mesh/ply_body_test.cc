#include "mesh/ply_body.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace meshseg::mesh_internal
