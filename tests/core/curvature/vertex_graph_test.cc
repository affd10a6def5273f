#include <algorithm>

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

}  // namespace
}  // namespace meshseg
