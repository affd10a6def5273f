#include "reconstruct/smoothing.h"

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

// An n × n vertex grid on z = 0, two triangles per cell.
void FlatGrid(int n, std::vector<Eigen::Vector3d>* vertices,
              std::vector<std::array<int, 3>>* triangles) {
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) vertices->emplace_back(x, y, 0.0);
  }
  for (int y = 0; y + 1 < n; ++y) {
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x;
      triangles->push_back({a, a + 1, a + n + 1});
      triangles->push_back({a, a + n + 1, a + n});
    }
  }
}

TEST(SmoothSelected, PullsABumpBackAndLeavesTheRestAlone) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  FlatGrid(9, &vertices, &triangles);
  std::vector<uint8_t> selected(vertices.size(), 0);
  for (const int v : {39, 40, 41}) {  // the middle of row 4, lifted
    vertices[v].z() = 1.0;
    selected[v] = 1;
  }
  const auto before = vertices;
  SmoothSelected(triangles, selected, 0.5, 30, &vertices);
  for (size_t v = 0; v < vertices.size(); ++v) {
    if (selected[v]) {
      EXPECT_LT(std::abs(vertices[v].z()), 0.1) << v;
    } else {
      EXPECT_EQ(vertices[v], before[v]) << v;
    }
  }
}

TEST(SmoothSelected, KeepsAFlatMeshFlat) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  FlatGrid(6, &vertices, &triangles);
  const std::vector<uint8_t> all(vertices.size(), 1);
  SmoothSelected(triangles, all, 0.5, 30, &vertices);
  for (const auto& v : vertices) EXPECT_DOUBLE_EQ(v.z(), 0.0);
}

// A vertex of a flat face joined by one long edge to a vertex 10 units off
// the face (as the marching-tetrahedra surface joins the two sides of a thin
// wall): weighted by 1/|e| the far vertex counts about a tenth of a near one,
// so the vertex stays within 0.25 of its face; with equal weights it would
// settle at the plain mean of its 7 neighbours, 10/7 ≈ 1.4 off.
TEST(SmoothSelected, ALongEdgeToTheFarSideBarelyPullsAVertexOffItsFace) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  FlatGrid(5, &vertices, &triangles);
  const int center = 12;
  const int far = static_cast<int>(vertices.size());
  vertices.emplace_back(2.0, 2.0, -10.0);
  triangles.push_back({center, far, center + 1});
  std::vector<uint8_t> selected(vertices.size(), 0);
  selected[center] = 1;
  SmoothSelected(triangles, selected, 0.5, 30, &vertices);
  EXPECT_LT(std::abs(vertices[center].z()), 0.25);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
