#include "curvature/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "test_meshes.h"

namespace meshseg::curvature_internal {
namespace {

// A wavy 40 x 30 grid: rows in scan order, as a scanned or voxel mesh comes.
absl::StatusOr<Mesh> WavyGrid() {
  return testing::MakeGrid(40, 30, [](double s, double t) {
    return Eigen::Vector3d(40.0 * s, 30.0 * t, std::sin(6.0 * s) * std::cos(5.0 * t));
  }, "wavy");
}

TEST(MortonOrderedGraph, IsARenumberingThatKeepsEachRowsOrder) {
  const absl::StatusOr<Mesh> mesh = WavyGrid();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const VertexGraph g = BuildVertexGraph(mesh->tri);
  const OrderedGraph walk = MortonOrderedGraph(mesh->tri);
  const int n = g.vertex_count();
  ASSERT_EQ(walk.graph.vertex_count(), n);
  ASSERT_EQ(walk.order.size(), static_cast<std::size_t>(n));
  std::vector<int> sorted = walk.order;
  std::sort(sorted.begin(), sorted.end());
  for (int v = 0; v < n; ++v) ASSERT_EQ(sorted[v], v) << "order is not a permutation";
  for (int k = 0; k < n; ++k) {
    const int v = walk.order[k];
    ASSERT_EQ(walk.rank[v], k);
    EXPECT_EQ(walk.graph.positions[k], g.positions[v]);
    const auto row = walk.graph.Neighbors(k);
    const auto own = g.Neighbors(v);
    ASSERT_EQ(row.size(), own.size()) << "vertex " << v;
    for (std::size_t i = 0; i < row.size(); ++i) EXPECT_EQ(walk.order[row[i]], own[i]);
  }
  // Not the identity: a scan-ordered grid is not in Morton order.
  int moved = 0;
  for (int k = 0; k < n; ++k) moved += walk.order[k] != k;
  EXPECT_GT(moved, n / 2);
}

TEST(MortonOrderedGraph, NeighbourhoodsAreTheSameVerticesInTheSameOrder) {
  const absl::StatusOr<Mesh> mesh = WavyGrid();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const VertexGraph g = BuildVertexGraph(mesh->tri);
  const OrderedGraph walk = MortonOrderedGraph(mesh->tri);
  // Every fifth vertex excluded, as the sharp vertices in pass 2.
  std::vector<uint8_t> excluded(g.vertex_count(), 0);
  for (std::size_t v = 0; v < excluded.size(); v += 5) excluded[v] = 1;
  const std::vector<uint8_t> excluded_walk = walk.Permuted<uint8_t>(excluded);
  NeighborhoodScratch scratch;
  std::vector<int> own;
  std::vector<int> renumbered;
  for (int v = 0; v < g.vertex_count(); ++v) {
    for (const bool exclude : {false, true}) {
      CollectNeighborhood(g, v, 3.5, exclude ? excluded : std::vector<uint8_t>{}, &scratch, &own,
                          30);
      CollectNeighborhood(walk.graph, walk.rank[v], 3.5,
                          exclude ? excluded_walk : std::vector<uint8_t>{}, &scratch,
                          &renumbered, 30);
      for (int& j : renumbered) j = walk.order[j];
      ASSERT_EQ(own, renumbered) << "vertex " << v << (exclude ? " with exclusions" : "");
    }
  }
}

}  // namespace
}  // namespace meshseg::curvature_internal
