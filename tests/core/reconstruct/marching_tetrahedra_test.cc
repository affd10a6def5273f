#include "reconstruct/marching_tetrahedra.h"

#include <map>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "grid_supports.h"
#include "reconstruct/graph_cut.h"

namespace meshseg::reconstruct_internal {
namespace {

TEST(MarchingTetrahedra, SphereFieldGivesAClosedOrientedSurfaceOnTheZeroSet) {
  const auto supports = test::GridSupports(11, 2.0);
  const PuFunction pu(supports);
  const TetMesh tets = *RegularTetrahedralization(supports, {});
  std::vector<Eigen::Vector3d> position;
  std::vector<double> f;
  for (const int s : tets.support) {
    position.push_back(supports[s].center);
    f.push_back(pu(supports[s].center));
  }
  const auto inside = SignLabels(tets, f);
  const std::vector<uint8_t> sparse(position.size(), 0);
  const auto surface = MarchingTetrahedra(tets, position, f, inside, sparse, pu, {});
  ASSERT_TRUE(surface.ok()) << surface.status();
  ASSERT_FALSE(surface->triangles.empty());
  // On the zero set of f, which is near the unit sphere.
  double worst = 0.0;
  for (const auto& v : surface->vertices) worst = std::max(worst, std::abs(pu(v)));
  EXPECT_LT(worst, 0.02);
  for (const auto& v : surface->vertices) EXPECT_NEAR(v.norm(), 1.0, 0.1);
  for (const uint8_t s : surface->to_smooth) EXPECT_EQ(s, 0);
  // Closed: every edge is used once in each direction.
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : surface->triangles) {
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  // Oriented outward: positive signed volume.
  double volume = 0.0;
  for (const auto& t : surface->triangles) {
    volume +=
        surface->vertices[t[0]].dot(surface->vertices[t[1]].cross(surface->vertices[t[2]])) / 6;
  }
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI, 0.4);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
