#include "reconstruct/octree.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

std::vector<Eigen::Vector3d> SpherePoints(int count) {
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    points.push_back(0.4 * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  return points;
}

TEST(BalancedOctreeLeaves, TileTheCubeRefineAtPointsAndDifferByOneLevel) {
  const auto points = SpherePoints(500);
  const Eigen::Vector3d origin = Eigen::Vector3d::Constant(-0.5);
  constexpr int kLevel = 5;
  const auto leaves = BalancedOctreeLeaves(points, origin, 1.0, kLevel, {});
  ASSERT_TRUE(leaves.ok()) << leaves.status();
  double volume = 0.0;
  for (const auto& leaf : *leaves) volume += std::pow(leaf.size, 3);
  EXPECT_NEAR(volume, 1.0, 1e-9);
  // Every point lies in a max-level leaf.
  for (const auto& p : points) {
    int level = -1;
    for (const auto& leaf : *leaves) {
      if (((p - leaf.center).cwiseAbs().array() <= 0.5 * leaf.size).all()) level = leaf.level;
    }
    EXPECT_EQ(level, kLevel);
  }
  // Leaves that touch (share a face, edge or corner) differ by at most one level.
  for (const auto& a : *leaves) {
    for (const auto& b : *leaves) {
      const double reach = 0.5 * (a.size + b.size) + 1e-9;
      if (((a.center - b.center).cwiseAbs().array() <= reach).all()) {
        ASSERT_LE(std::abs(a.level - b.level), 1);
      }
    }
  }
}

TEST(BalancedOctreeLeaves, StopRequestIsCancelled) {
  std::stop_source stop;
  stop.request_stop();
  RunContext ctx;
  ctx.stop = stop.get_token();
  const auto leaves =
      BalancedOctreeLeaves(SpherePoints(10), Eigen::Vector3d::Constant(-0.5), 1.0, 4, ctx);
  EXPECT_EQ(leaves.status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
