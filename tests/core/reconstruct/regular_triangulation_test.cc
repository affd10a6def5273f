#include "reconstruct/regular_triangulation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "grid_supports.h"

namespace meshseg::reconstruct_internal {
namespace {

TEST(RegularTetrahedralization, EqualWeightsGiveTheDelaunayTetrahedraOfAGrid) {
  const auto supports = test::GridSupports(5, 1.0);  // 4³ cubes
  const auto tets = RegularTetrahedralization(supports, {});
  ASSERT_TRUE(tets.ok()) << tets.status();
  EXPECT_EQ(tets->support.size(), supports.size());
  // Each tet in positive order (marching tetrahedra orients by it); their
  // volumes add up to the cube [−1, 1]³.
  double volume = 0.0;
  for (const auto& t : tets->tets) {
    const Eigen::Vector3d a = supports[tets->support[t[0]]].center;
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i) m.col(i) = supports[tets->support[t[i + 1]]].center - a;
    EXPECT_GT(m.determinant(), 0.0);
    volume += m.determinant() / 6;
  }
  EXPECT_NEAR(volume, 8.0, 1e-9);
  // Hull vertices are the 5³ − 3³ nodes on the cube's boundary.
  int hull = 0;
  for (const uint8_t h : tets->on_hull) hull += h;
  EXPECT_EQ(hull, 125 - 27);
  for (const auto& e : tets->edges) EXPECT_LT(e[0], e[1]);
}

TEST(RegularTetrahedralization, SmallBallInsideALargeOneIsHidden) {
  auto supports = test::GridSupports(3, 1.0);
  Support small;
  small.center = Eigen::Vector3d(0.1, 0.05, 0.0);  // next to the centre node
  small.radius = 0.05;
  supports[13].radius = 1.2;  // the centre node (1, 1, 1) grows
  supports.push_back(small);
  const auto tets = RegularTetrahedralization(supports, {});
  ASSERT_TRUE(tets.ok()) << tets.status();
  EXPECT_EQ(tets->support.size(), supports.size() - 1);
  EXPECT_EQ(
      std::count(tets->support.begin(), tets->support.end(), static_cast<int>(supports.size() - 1)),
      0);
}

// Given weights replace r²: the small centre of the test above, weighted
// just above the largest r_i² − |c − c_i|² (so it lies in its own power
// cell) and below the centre node's r² + |c − c_0|² (so that stays), is a
// vertex; a support weighted −1 is none.
TEST(RegularTetrahedralization, GivenWeightsReplaceTheSquaredRadii) {
  auto supports = test::GridSupports(3, 1.0);
  Support small;
  small.center = Eigen::Vector3d(0.1, 0.05, 0.0);
  small.radius = 0.05;
  supports[13].radius = 1.2;
  supports.push_back(small);
  std::vector<double> weights(supports.size());
  for (size_t i = 0; i < supports.size(); ++i) weights[i] = supports[i].radius * supports[i].radius;
  double lo = 0.0;
  for (size_t i = 0; i + 1 < supports.size(); ++i) {
    lo = std::max(lo, weights[i] - (supports[i].center - small.center).squaredNorm());
  }
  ASSERT_LT(lo + 0.005, 1.44 + small.center.squaredNorm());
  weights.back() = lo + 0.005;
  weights[0] = -1.0;
  const auto tets = RegularTetrahedralization(supports, weights, {});
  ASSERT_TRUE(tets.ok()) << tets.status();
  EXPECT_EQ(tets->support.size(), supports.size() - 1);
  EXPECT_EQ(std::count(tets->support.begin(), tets->support.end(), 0), 0);
  EXPECT_EQ(
      std::count(tets->support.begin(), tets->support.end(), static_cast<int>(supports.size() - 1)),
      1);
}

TEST(RegularTetrahedralization, CoplanarCentresAreInvalid) {
  std::vector<Support> flat(4);
  for (int i = 0; i < 4; ++i) {
    flat[i].center = Eigen::Vector3d(i % 2, i / 2, 0.0);
    flat[i].radius = 0.5;
  }
  EXPECT_EQ(RegularTetrahedralization(flat, {}).status().code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
