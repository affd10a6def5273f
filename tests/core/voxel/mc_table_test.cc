#include "voxel/mc_table.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>

namespace meshseg::voxel_internal {
namespace {

int CrossingEdgeCount(int mask) {
  int n = 0;
  for (const auto& e : kCubeEdgeCorners) n += ((mask >> e[0]) & 1) != ((mask >> e[1]) & 1);
  return n;
}

TEST(BuildMcTable, EmptyAndFullCubesHaveNoTriangles) {
  const McTable table = BuildMcTable();
  EXPECT_TRUE(table[0].empty());
  EXPECT_TRUE(table[255].empty());
}

TEST(BuildMcTable, EveryCrossingEdgeIsUsedAndLoopsAreClosed) {
  const McTable table = BuildMcTable();
  for (int mask = 1; mask < 255; ++mask) {
    // Directed edges of the triangles: the boundary of each case's patch is
    // made of contour segments, each used once; interior diagonals cancel.
    std::map<std::pair<int, int>, int> directed;
    std::map<int, int> used;
    for (const auto& t : table[mask]) {
      for (int c = 0; c < 3; ++c) {
        ++directed[{t[c], t[(c + 1) % 3]}];
        used[t[c]] = 1;
      }
    }
    EXPECT_EQ(static_cast<int>(used.size()), CrossingEdgeCount(mask)) << "case " << mask;
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1) << "case " << mask << " repeats a directed edge";
    }
  }
}

TEST(BuildMcTable, SingleInsideCornerGivesOneTriangleFacingOut) {
  const McTable table = BuildMcTable();
  ASSERT_EQ(table[1].size(), 1u);  // corner 0 inside
  // Edges 0 (x), 4 (y), 8 (z) from corner 0: counter-clockwise seen from
  // (1, 1, 1) is the cyclic order 0 -> 4 -> 8.
  const auto& t = table[1][0];
  const int rot = t[0] == 0 ? 0 : t[1] == 0 ? 1 : 2;
  EXPECT_EQ(t[rot], 0);
  EXPECT_EQ(t[(rot + 1) % 3], 4);
  EXPECT_EQ(t[(rot + 2) % 3], 8);
}

TEST(BuildMcTable, ComplementaryCasesWithoutAmbiguityAreReversed) {
  const McTable table = BuildMcTable();
  // Case 3 (corners 0, 1 inside) and 252 are the same quad, facing opposite ways.
  EXPECT_EQ(table[3].size(), 2u);
  EXPECT_EQ(table[252].size(), 2u);
}

}  // namespace
}  // namespace meshseg::voxel_internal
