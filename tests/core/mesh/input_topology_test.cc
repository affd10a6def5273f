#include "mesh/input_topology.h"

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

TEST(AnalyzeInputTopology, CountsFinEdgeAndMarksDuplicates) {
  // Triangles 0..2 share edge 0-1 (a fin); 3 repeats 0 reversed.
  const LargeVector<std::array<int, 3>> tris = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 1, 0}};
  LargeVector<uint8_t> keep(tris.size(), 1);
  const TopologyCounts c = AnalyzeInputTopology(5, tris, &keep);
  EXPECT_EQ(c.non_manifold_edge_count, 1);
  EXPECT_EQ(c.duplicate_face_count, 1);
  EXPECT_EQ(keep, (LargeVector<uint8_t>{1, 1, 1, 0}));
}

TEST(AnalyzeInputTopology, CountsPinchedVertexAndIgnoresDroppedTriangles) {
  // A bow tie at vertex 0, and a dropped triangle that would join the fans.
  const LargeVector<std::array<int, 3>> tris = {{0, 1, 2}, {0, 3, 4}, {0, 2, 3}};
  LargeVector<uint8_t> keep = {1, 1, 0};
  const TopologyCounts c = AnalyzeInputTopology(5, tris, &keep);
  EXPECT_EQ(c.non_manifold_vertex_count, 1);
  EXPECT_EQ(c.non_manifold_edge_count, 0);
  keep = {1, 1, 1};
  EXPECT_EQ(AnalyzeInputTopology(5, tris, &keep).non_manifold_vertex_count, 0);
}

TEST(AnalyzeInputTopology, FindsNothingOnClosedTetrahedron) {
  const LargeVector<std::array<int, 3>> tris = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  LargeVector<uint8_t> keep(4, 1);
  const TopologyCounts c = AnalyzeInputTopology(4, tris, &keep);
  EXPECT_EQ(c.non_manifold_edge_count, 0);
  EXPECT_EQ(c.non_manifold_vertex_count, 0);
  EXPECT_EQ(c.duplicate_face_count, 0);
}

}  // namespace
}  // namespace meshseg::mesh_internal
