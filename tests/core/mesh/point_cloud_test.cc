// ReadPointCloud (dispatch, normalised normals) and WritePointCloud.
#include "meshseg/point_cloud.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;
using testing_files::WriteTemp;

std::string Data(const std::string& name) {
  return std::string(MESHSEG_SHARED_DATA_DIR) + "/" + name;
}

TEST(ReadPointCloud, ReadsBrokenBulletWithUnitNormals) {
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(Data("broken_bullet_50k.xyz"));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  EXPECT_EQ(cloud->points.size(), 50000u);
  ASSERT_TRUE(cloud->has_normals());
  for (const Eigen::Vector3d& n : cloud->normals) ASSERT_NEAR(n.norm(), 1.0, 1e-12);
  EXPECT_EQ(cloud->name, "broken_bullet_50k.xyz");
}

TEST(ReadPointCloud, ReadsScanWithoutNormals) {
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(Data("abc_00016513_scan.xyz"));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  EXPECT_EQ(cloud->points.size(), 86648u);
  EXPECT_FALSE(cloud->has_normals());
}

TEST(ReadPointCloud, ReadsPlyVerticesWithNormals) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n"
      "0 0 0 0 0 2\n1 2 3 3 0 4\n";
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(WriteTemp("cloud.ply", text));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  ASSERT_EQ(cloud->points.size(), 2u);
  EXPECT_EQ(cloud->points[1], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(cloud->normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR((cloud->normals[1] - Eigen::Vector3d(0.6, 0, 0.8)).norm(), 0.0, 1e-15);
}

TEST(ReadPointCloud, ReadsMeshVerticesAsPoints) {
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(Data("bunny_zipper_res2.ply"));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  EXPECT_EQ(cloud->points.size(), 8171u);
  EXPECT_FALSE(cloud->has_normals());
}

TEST(ReadPointCloud, RejectsZeroNormal) {
  const absl::StatusOr<PointCloud> cloud =
      ReadPointCloud(WriteTemp("zero_normal.xyz", "0 0 0 0 0 1\n1 1 1 0 0 0\n"));
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()),
              HasSubstr("read_point_cloud: \"zero_normal.xyz\": point 1 has a zero"));
}

TEST(ReadPointCloud, ReportsMissingFileAsNotFound) {
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud("/nonexistent/scan.xyz");
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kNotFound) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr("\"scan.xyz\""));
}

TEST(ReadPointCloud, RejectsMeshFormats) {
  const absl::StatusOr<PointCloud> cloud =
      ReadPointCloud(WriteTemp("cube.off", testing_files::CubeOff()));
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr("unknown point-cloud format \"off\""));
}

TEST(ReadPointCloud, RejectsTruncatedBinaryPly) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  bytes.append(20, '\0');  // 24 needed
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(WriteTemp("truncated.ply", bytes));
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr("\"truncated.ply\""));
  EXPECT_THAT(Message(cloud.status()), HasSubstr("only 20 bytes follow"));
}

TEST(WritePointCloud, RoundTripsExactlyWithAndWithoutNormals) {
  PointCloud cloud;
  cloud.points = {{1.0 / 3, -2.5e-7, 1e10}, {0.1, 0.2, 0.3}};
  for (bool normals : {false, true}) {
    if (normals) cloud.normals = {{0, 0, 1}, {0.6, 0.8, 0}};
    const std::string path = WriteTemp(normals ? "with.xyz" : "without.xyz", "");
    ASSERT_TRUE(WritePointCloud(cloud, path).ok());
    const absl::StatusOr<PointCloud> back = ReadPointCloud(path);
    ASSERT_TRUE(back.ok()) << back.status();
    EXPECT_EQ(back->points, cloud.points);
    EXPECT_EQ(back->has_normals(), normals);
    if (normals) {
      EXPECT_EQ(back->normals, cloud.normals);
    }
  }
}

TEST(WritePointCloud, RejectsNormalCountMismatch) {
  PointCloud cloud;
  cloud.points = {{0, 0, 0}, {1, 1, 1}};
  cloud.normals = {{0, 0, 1}};
  const absl::Status status = WritePointCloud(cloud, WriteTemp("bad.xyz", ""));
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(status), HasSubstr("1 normals for 2 points"));
}

}  // namespace
}  // namespace meshseg
