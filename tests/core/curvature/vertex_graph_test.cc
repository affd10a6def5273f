#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "test_meshes.h"

namespace meshseg {
namespace {

TEST(CollectNeighborhood, TakesConnectedVerticesInsideTheRadius) {
  // Unit grid 11 x 11 in the plane z = 0.
  auto mesh = testing::MakeGrid(11, 11, [](double s, double t) {
    return Eigen::Vector3d(10.0 * s, 10.0 * t, 0.0);
  }, "grid");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const VertexGraph g = BuildVertexGraph(mesh->tri);
  ASSERT_EQ(g.vertex_count(), 121);
  const int center = 5 * 11 + 5;
  NeighborhoodScratch scratch;
  std::vector<int> out;
  CollectNeighborhood(g, center, 2.5, {}, &scratch, &out);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.front(), center);
  // Grid points within distance 2.5 of (5, 5): 21 of them.
  EXPECT_EQ(out.size(), 21u);

  // Excluding the column x = 6 cuts the right half off.
  std::vector<uint8_t> excluded(121, 0);
  for (int j = 0; j < 11; ++j) excluded[j * 11 + 6] = 1;
  CollectNeighborhood(g, center, 2.5, excluded, &scratch, &out);
  for (const int v : out) EXPECT_LT(g.positions[v].x(), 5.5) << "vertex " << v;
}

// The walk one vertex at a time, with a branch per test, as it was written
// before the queue was filled without branches: the reference order.
std::vector<int> WalkOneAtATime(const VertexGraph& g, int i, double radius,
                                const std::vector<uint8_t>& excluded, std::size_t max_count) {
  std::vector<char> seen(g.vertex_count(), 0);
  std::vector<int> out{i};
  seen[i] = 1;
  for (std::size_t head = 0; head < out.size(); ++head) {
    if (max_count != 0 && out.size() >= max_count) break;
    for (const int j : g.Neighbors(out[head])) {
      if (seen[j]) continue;
      seen[j] = 1;
      if (!excluded.empty() && excluded[j] != 0) continue;
      if ((g.positions[j] - g.positions[i]).squaredNorm() >= radius * radius) continue;
      out.push_back(j);
      if (max_count != 0 && out.size() >= max_count) break;
    }
  }
  return out;
}

TEST(CollectNeighborhood, GivesTheOneAtATimeWalksVerticesInItsOrder) {
  // A wavy, sheared grid (rows of unequal edges), every seventh vertex
  // excluded; radii from under one edge (the centre alone) to past the
  // grid, caps that cut the walk inside a row and none. One scratch for
  // all walks, as a thread of the stage reuses it.
  auto mesh = testing::MakeGrid(37, 23, [](double s, double t) {
    return Eigen::Vector3d(36.0 * s + 3.0 * t * t, 22.0 * t,
                           2.0 * std::sin(7.0 * s) * std::cos(4.0 * t));
  }, "wavy");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const VertexGraph g = BuildVertexGraph(mesh->tri);
  std::vector<uint8_t> excluded(g.vertex_count(), 0);
  for (std::size_t v = 3; v < excluded.size(); v += 7) excluded[v] = 1;
  NeighborhoodScratch scratch;
  std::vector<int> out;
  int capped = 0;
  for (int i = 0; i < g.vertex_count(); i += 3) {
    for (const double radius : {0.5, 2.5, 4.7, 100.0}) {
      for (const std::size_t cap : {std::size_t{0}, std::size_t{1}, std::size_t{17},
                                    std::size_t{60}}) {
        for (const bool exclude : {false, true}) {
          const std::vector<uint8_t> ex = exclude ? excluded : std::vector<uint8_t>{};
          const std::vector<int> want = WalkOneAtATime(g, i, radius, ex, cap);
          CollectNeighborhood(g, i, radius, ex, &scratch, &out, cap);
          ASSERT_EQ(out, want) << "vertex " << i << " radius " << radius << " cap " << cap
                               << (exclude ? " with exclusions" : "");
          capped += cap != 0 && want.size() == cap && cap > 1;
        }
      }
    }
  }
  EXPECT_GT(capped, 100);  // the caps did cut walks short
}

}  // namespace
}  // namespace meshseg
