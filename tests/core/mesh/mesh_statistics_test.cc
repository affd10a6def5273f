#include <cmath>

#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

// Two unit cubes, the second shifted by (3, 0, 0): two components.
absl::StatusOr<Mesh> TwoCubes() {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<int, 3>> t;
  const std::vector<testing_files::Tri> cube = testing_files::CubeTriangles();
  for (int copy = 0; copy < 2; ++copy) {
    for (const auto& tri : cube) {
      std::array<int, 3> idx;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d p(tri[k][0] + 3.0 * copy, tri[k][1], tri[k][2]);
        auto it = std::find(v.begin(), v.end(), p);
        idx[k] = static_cast<int>(it - v.begin());
        if (it == v.end()) v.push_back(p);
      }
      t.push_back(idx);
    }
  }
  return BuildMesh(v, t, "two_cubes");
}

TEST(MeshStatistics, CountsTwoClosedCubes) {
  const absl::StatusOr<Mesh> mesh = TwoCubes();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshStats s = MeshStatistics(*mesh);
  EXPECT_EQ(s.vertex_count, 16);
  EXPECT_EQ(s.face_count, 24);
  EXPECT_EQ(s.input_face_count, 24);
  EXPECT_EQ(s.input_vertex_count, 16);
  EXPECT_EQ(s.component_count, 2);
  EXPECT_EQ(s.boundary_edge_count, 0);
  EXPECT_EQ(s.dropped_face_count, 0);
  EXPECT_EQ(s.isolated_vertex_count, 0);
  // Per cube: 12 unit edges and 6 face diagonals of length sqrt(2).
  EXPECT_NEAR(s.mean_edge_length, (12 + 6 * std::sqrt(2.0)) / 18, 1e-12);
  EXPECT_EQ(s.bbox_min, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(s.bbox_max, Eigen::Vector3d(4, 1, 1));
}

TEST(MeshStatistics, CountsBoundaryOfOpenCube) {
  std::vector<testing_files::Tri> cube = testing_files::CubeTriangles();
  cube.erase(cube.begin(), cube.begin() + 2);  // the bottom face
  const absl::StatusOr<Mesh> mesh =
      ReadMesh(testing_files::WriteTemp("open_cube.stl", testing_files::BinaryStl(cube)));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshStats s = MeshStatistics(*mesh);
  EXPECT_EQ(s.boundary_edge_count, 4);
  EXPECT_EQ(s.component_count, 1);
  EXPECT_EQ(s.input_face_count, 10);
}

TEST(MeshStatistics, HandlesMeshFilledByHand) {
  Mesh mesh;
  const auto a = mesh.tri.add_vertex({0, 0, 0});
  const auto b = mesh.tri.add_vertex({2, 0, 0});
  const auto c = mesh.tri.add_vertex({0, 2, 0});
  mesh.tri.add_face(a, b, c);
  const MeshStats s = MeshStatistics(mesh);
  EXPECT_EQ(s.input_face_count, 1);
  EXPECT_EQ(s.input_vertex_count, 3);
  EXPECT_EQ(s.boundary_edge_count, 3);
  EXPECT_NEAR(MeanEdgeLength(mesh.tri), (4 + 2 * std::sqrt(2.0)) / 3, 1e-12);
}

TEST(MeanEdgeLength, IsZeroWithoutEdges) { EXPECT_EQ(MeanEdgeLength(TriMesh()), 0.0); }

}  // namespace
}  // namespace meshseg
