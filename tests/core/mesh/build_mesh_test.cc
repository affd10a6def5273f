// BuildMesh: the dropping rules and the input-face map.
#include <array>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing_files::Message;

// A 3 x 1 strip of unit squares in the plane z = 0: vertices 0..3 at y = 0,
// 4..7 at y = 1.
std::vector<Eigen::Vector3d> Strip() {
  std::vector<Eigen::Vector3d> v;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) v.emplace_back(x, y, 0);
  }
  return v;
}

TEST(BuildMesh, DegenerateFaceInTheMiddleMapsToMinusOneAndLaterFacesKeepTheirPlace) {
  const std::vector<std::array<int, 3>> tris = {
      {0, 1, 5}, {0, 5, 4},
      {1, 2, 2},  // repeated index
      {1, 2, 3},  // zero area: three collinear points
      {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}};
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), tris, "strip");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_THAT(mesh->face_of_input, ElementsAre(0, 1, -1, -1, 2, 3, 4, 5));
  EXPECT_EQ(mesh->tri.n_faces(), 6u);
  EXPECT_EQ(mesh->input_topology.degenerate_face_count, 2);
  // Mesh face k has the corners of the input face that maps to it.
  std::vector<int> corners;
  for (const auto v : mesh->tri.fv_range(TriMesh::FaceHandle(2))) corners.push_back(v.idx());
  EXPECT_THAT(corners, ElementsAre(1, 2, 6));
  const MeshStats stats = MeshStatistics(*mesh);
  EXPECT_EQ(stats.dropped_face_count, 2);
  EXPECT_EQ(stats.degenerate_face_count, 2);
  EXPECT_EQ(stats.boundary_edge_count, 8);
}

TEST(BuildMesh, DropsExactDuplicatesInAnyCornerOrder) {
  const std::vector<std::array<int, 3>> tris = {{0, 1, 5}, {1, 5, 0}, {0, 5, 4}, {5, 1, 0}};
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), tris, "dup");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_THAT(mesh->face_of_input, ElementsAre(0, -1, 1, -1));
  EXPECT_EQ(mesh->input_topology.duplicate_face_count, 2);
}

TEST(BuildMesh, CountsNonManifoldEdgeAndDropsTheFaceOpenMeshRefuses) {
  // Three triangles on edge 0-1: the third cannot be added to a halfedge mesh.
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  const std::vector<std::array<int, 3>> tris = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const absl::StatusOr<Mesh> mesh = BuildMesh(v, tris, "fin");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_THAT(mesh->face_of_input, ElementsAre(0, 1, -1));
  EXPECT_EQ(mesh->input_topology.non_manifold_edge_count, 1);
  EXPECT_EQ(mesh->input_topology.refused_face_count, 1);
  EXPECT_EQ(MeshStatistics(*mesh).non_manifold_edge_count, 1);
}

TEST(BuildMesh, CountsNonManifoldVertexOfTwoFans) {
  // Two triangles touching only at vertex 0 (a bow tie).
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  const absl::StatusOr<Mesh> mesh = BuildMesh(v, {{0, 1, 2}, {0, 3, 4}}, "bowtie");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->input_topology.non_manifold_vertex_count, 1);
  EXPECT_EQ(mesh->input_topology.non_manifold_edge_count, 0);
  EXPECT_EQ(mesh->tri.n_faces(), 2u);  // OpenMesh holds a bow tie
  EXPECT_EQ(MeshStatistics(*mesh).component_count, 2);
}

TEST(BuildMesh, KeepsUnreferencedVerticesInOrder) {
  std::vector<Eigen::Vector3d> v = Strip();
  const absl::StatusOr<Mesh> mesh = BuildMesh(v, {{0, 1, 5}}, "lonely");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->tri.n_vertices(), 8u);
  EXPECT_EQ(ToEigen(mesh->tri.point(TriMesh::VertexHandle(7))), v[7]);
  EXPECT_EQ(MeshStatistics(*mesh).isolated_vertex_count, 5);
}

TEST(BuildMesh, SetsUnitNormals) {
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), {{0, 1, 5}, {0, 5, 4}}, "n");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  for (const auto f : mesh->tri.faces()) {
    EXPECT_NEAR((ToEigen(mesh->tri.normal(f)) - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-15);
  }
  EXPECT_NEAR((ToEigen(mesh->tri.normal(TriMesh::VertexHandle(0))) - Eigen::Vector3d(0, 0, 1))
                  .norm(), 0.0, 1e-15);
}

TEST(BuildMesh, RejectsOutOfRangeIndex) {
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), {{0, 1, 5}, {0, 5, 8}}, "part_7");
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()),
              HasSubstr("build_mesh: \"part_7\": face 1: vertex index 8 out of range [0, 8)"));
}

TEST(BuildMesh, RejectsNanVertex) {
  std::vector<Eigen::Vector3d> v = Strip();
  v[3].y() = std::numeric_limits<double>::quiet_NaN();
  const absl::StatusOr<Mesh> mesh = BuildMesh(v, {{0, 1, 5}}, "nan_part");
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr("\"nan_part\": vertex 3 has a non-finite"));
}

TEST(BuildMesh, RejectsNoTriangles) {
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), {}, "empty");
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr("\"empty\": no faces"));
}

TEST(BuildMesh, RejectsOnlyDegenerateTriangles) {
  const absl::StatusOr<Mesh> mesh = BuildMesh(Strip(), {{0, 1, 2}, {4, 4, 5}}, "flat");
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(Message(mesh.status()), HasSubstr("\"flat\": all 2 faces dropped (2 degenerate"));
}

}  // namespace
}  // namespace meshseg
