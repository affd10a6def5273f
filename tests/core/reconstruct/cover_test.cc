#include "reconstruct/cover.h"

#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

TEST(CoverBySupports, EveryLeafLiesInsideASupportAndTheOrderFollowsTheSeed) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    points.push_back(0.4 * n);
    normals.push_back(-n);
  }
  const mesh_internal::PointIndex index(points);
  const Eigen::Vector3d origin = Eigen::Vector3d::Constant(-0.5);
  const auto leaves = *BalancedOctreeLeaves(points, origin, 1.0, 5, {});
  const FitInput in{points, normals, index, 0.01, 2.0};
  const auto a = CoverBySupports(leaves, in, /*seed=*/1, {});
  const auto b = CoverBySupports(leaves, in, /*seed=*/2, {});
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_LT(a->size(), leaves.size());  // a ball covers several cells
  for (const auto& leaf : leaves) {
    bool covered = false;
    for (const auto& s : *a) {
      const Eigen::Vector3d far = (leaf.center - s.center).cwiseAbs().array() + 0.5 * leaf.size;
      covered = covered || far.norm() <= s.radius;
    }
    ASSERT_TRUE(covered) << leaf.center.transpose();
  }
  EXPECT_NE(a->front().center, b->front().center);
  for (const auto& s : *a) EXPECT_GE(s.radius, 0.75 * std::sqrt(3.0) / 32 - 1e-12);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
