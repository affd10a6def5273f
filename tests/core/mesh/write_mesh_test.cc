// Writers: round trips through ReadMesh, and the coloured PLY.
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/label_color.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "temp_file.h"
#include "server/test_files.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;

// A unit cube with coordinates that need all 17 digits.
absl::StatusOr<Mesh> OddCube() {
  absl::StatusOr<Mesh> mesh =
      ReadMesh(testing_files::WriteTemp("cube.off", testing_files::CubeOff()));
  if (mesh.ok()) {
    for (const auto v : mesh->tri.vertices()) mesh->tri.point(v) *= 1.0 / 3.0;
  }
  return mesh;
}

void ExpectSameMesh(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (const auto v : a.vertices()) EXPECT_EQ(a.point(v), b.point(v)) << "vertex " << v.idx();
  for (const auto f : a.faces()) {
    std::vector<int> ca, cb;
    for (const auto v : a.fv_range(f)) ca.push_back(v.idx());
    for (const auto v : b.fv_range(f)) cb.push_back(v.idx());
    EXPECT_EQ(ca, cb) << "face " << f.idx();
  }
}

TEST(WriteMesh, RoundTripsExactlyThroughBinaryPly) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::string path = testing_files::WriteTemp("out.ply", "");
  ASSERT_TRUE(WriteMesh(mesh->tri, path).ok());
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  ExpectSameMesh(mesh->tri, back->tri);
}

TEST(WriteMesh, RoundTripsExactlyThroughOff) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::string path = testing_files::WriteTemp("out.off", "");
  ASSERT_TRUE(WriteMesh(mesh->tri, path).ok());
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  ExpectSameMesh(mesh->tri, back->tri);
}

TEST(WriteMesh, RoundTripsExactlyThroughObj) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::string path = testing_files::WriteTemp("out.obj", "");
  ASSERT_TRUE(WriteMesh(mesh->tri, path).ok());
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  ExpectSameMesh(mesh->tri, back->tri);
}

// STL holds float32: every vertex read back is a vertex rounded to float,
// welded again into the same closed cube.
TEST(WriteMesh, WritesBinaryStlInFloat32) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::string path = testing_files::WriteTemp("out.stl", "");
  ASSERT_TRUE(WriteMesh(mesh->tri, path).ok());
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_EQ(back->tri.n_faces(), mesh->tri.n_faces());
  ASSERT_EQ(back->tri.n_vertices(), mesh->tri.n_vertices());
  std::set<std::array<float, 3>> rounded;
  for (const auto v : mesh->tri.vertices()) {
    const auto& p = mesh->tri.point(v);
    rounded.insert({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  }
  for (const auto v : back->tri.vertices()) {
    const auto& p = back->tri.point(v);
    EXPECT_TRUE(rounded.count({static_cast<float>(p[0]), static_cast<float>(p[1]),
                               static_cast<float>(p[2])}))
        << "vertex " << v.idx();
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], static_cast<double>(static_cast<float>(p[c])));
  }
  for (const auto e : back->tri.edges()) EXPECT_FALSE(back->tri.is_boundary(e));
}

TEST(WriteMesh, RejectsOtherExtensions) {
  const absl::Status status = WriteMesh(TriMesh(), testing_files::WriteTemp("out.xyz", ""));
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(status), HasSubstr("\"out.xyz\": unsupported extension \"xyz\""));
}

TEST(WriteMesh, ReportsUnwritablePathAsInternal) {
  const absl::Status status = WriteMesh(TriMesh(), "/nonexistent/dir/out.ply");
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(Message(status), HasSubstr("\"out.ply\""));
}

TEST(WriteColoredPly, GivesEachLabelItsOwnColourAndGreyToMinusOne) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::vector<int> labels = {0, 0, 1, 1, 2, 2, 3, 3, 4, 5, -1, -1};
  const std::string path = testing_files::WriteTemp("labels.ply", "");
  ASSERT_TRUE(WriteColoredPly(mesh->tri, labels, path).ok());
  // Read the colours back: 12 faces of 1 + 12 + 3 bytes at the end of the file.
  const std::string bytes = testing_files::ReadText(path);
  EXPECT_THAT(bytes, HasSubstr("property uchar red\nproperty uchar green\nproperty uchar blue\n"));
  const size_t faces = bytes.size() - 12 * 16;
  std::vector<std::array<uint8_t, 3>> colors;
  for (int f = 0; f < 12; ++f) {
    const char* c = bytes.data() + faces + f * 16 + 13;
    colors.push_back({static_cast<uint8_t>(c[0]), static_cast<uint8_t>(c[1]),
                      static_cast<uint8_t>(c[2])});
  }
  EXPECT_EQ(colors[0], colors[1]);
  EXPECT_EQ(colors[10], (std::array<uint8_t, 3>{128, 128, 128}));
  std::set<std::array<uint8_t, 3>> distinct(colors.begin(), colors.end());
  EXPECT_EQ(distinct.size(), 7u);  // labels 0..5 and grey
  EXPECT_EQ(colors[2], LabelColor(1)) << "the palette the HTML report shares";
  // The file is still a mesh we read.
  const absl::StatusOr<Mesh> back = ReadMesh(path);
  ASSERT_TRUE(back.ok()) << back.status();
  ExpectSameMesh(mesh->tri, back->tri);
}

TEST(WriteColoredPly, RejectsWrongLabelCount) {
  const absl::StatusOr<Mesh> mesh = OddCube();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const absl::Status status =
      WriteColoredPly(mesh->tri, {1, 2}, testing_files::WriteTemp("labels.ply", ""));
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(status), HasSubstr("2 face labels for 12 faces"));
}

// The coloured points read back as the same points (ReadPointCloud reads
// PLY vertices), and the colours follow the labels.
TEST(WriteColoredPointPly, WritesThePointsWithOneColourPerLabel) {
  PointCloud cloud;
  for (int i = 0; i < 5; ++i) cloud.points.emplace_back(i / 3.0, 1.0 - i / 7.0, 2.0 * i);
  const std::vector<int> labels = {2, 2, 0, -1, 7};
  const std::string path = testing_files::WriteTemp("points.ply", "");
  ASSERT_TRUE(WriteColoredPointPly(cloud, labels, path).ok());
  const absl::StatusOr<PointCloud> back = ReadPointCloud(path);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->points, cloud.points);
  const std::string bytes = testing_files::ReadText(path);
  ASSERT_GE(bytes.size(), 5u * 27);
  std::vector<std::array<uint8_t, 3>> colors;
  for (int i = 0; i < 5; ++i) {
    const char* c = bytes.data() + bytes.size() - (5 - i) * 27 + 24;
    colors.push_back({static_cast<uint8_t>(c[0]), static_cast<uint8_t>(c[1]),
                      static_cast<uint8_t>(c[2])});
  }
  EXPECT_EQ(colors[0], colors[1]);
  EXPECT_EQ(colors[3], (std::array<uint8_t, 3>{128, 128, 128}));
  const std::set<std::array<uint8_t, 3>> distinct(colors.begin(), colors.end());
  EXPECT_EQ(distinct.size(), 4u);  // labels 2, 0, 7 and grey
}

TEST(WriteColoredPointPly, RejectsWrongLabelCount) {
  PointCloud cloud;
  cloud.points.assign(3, Eigen::Vector3d::Zero());
  const absl::Status status =
      WriteColoredPointPly(cloud, {1}, testing_files::WriteTemp("points.ply", ""));
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(status), HasSubstr("1 point labels for 3 points"));
}

}  // namespace
}  // namespace meshseg
