#include "reconstruct/cover.h"

#include <cmath>
#include <random>

#include "reconstruct/pu_function.h"
#include "reconstruct/regular_triangulation.h"

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

// A slab 40 × 40 × 10 (z in [-10, 0]) sampled every 0.5 on its top and its
// four sides, not on its bottom (the side it stood on), exact points with
// inward normals. A support whose ball holds its plane reads the solid
// under it as deep as its radius, so each support on the top near its
// middle (its foot among its own points) has an inner support centred a
// radius below the top, along its m. That centre is a tet vertex (it lies on
// the parent's sphere, so that ball does not hide it), and f is positive
// there where it lies in the slab.
TEST(CoverBySupports, ASupportOnAPlaneAddsAnInnerSupportARadiusInsideIt) {
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = -40; i <= 40; ++i) {
    const double x = 0.5 * i;
    for (int j = -40; j <= 40; ++j) {
      points.emplace_back(x, 0.5 * j, 0.0);
      normals.emplace_back(0, 0, -1);
    }
    for (int k = 1; k <= 20; ++k) {
      for (const double side : {-20.0, 20.0}) {
        points.emplace_back(x, side, -0.5 * k);
        normals.emplace_back(0, -side / 20, 0);
        if (std::abs(i) < 40) {
          points.emplace_back(side, x, -0.5 * k);
          normals.emplace_back(-side / 20, 0, 0);
        }
      }
    }
  }
  const mesh_internal::PointIndex index(points);
  const auto leaves = *BalancedOctreeLeaves(points, Eigen::Vector3d::Constant(-32), 64.0, 6, {});
  const FitInput in{points, normals, index, 0.05, std::sqrt(3.0) * 64.0};
  const auto supports = CoverBySupports(leaves, in, /*seed=*/1, {});
  ASSERT_TRUE(supports.ok());
  const auto tets = RegularTetrahedralization(*supports, {});
  ASSERT_TRUE(tets.ok());
  std::vector<uint8_t> vertex(supports->size(), 0);
  for (const int s : tets->support) vertex[s] = 1;
  const PuFunction f(*supports);
  int parents = 0;
  for (const Support& s : *supports) {
    const double height = s.g(s.center);
    if (!(s.point_count > 0 && std::abs(s.center.z()) < 1 && s.center.head<2>().norm() < 10)) {
      continue;
    }
    ++parents;
    const Eigen::Vector3d at = s.center + (s.radius - height) * s.m;
    ASSERT_NEAR(at.z(), -s.radius, 1e-6);
    size_t inner = supports->size();
    for (size_t k = 0; k < supports->size(); ++k) {
      if (((*supports)[k].center - at).norm() < 1e-9) inner = k;
    }
    ASSERT_LT(inner, supports->size()) << "no inner support below " << s.center.transpose();
    EXPECT_TRUE(vertex[inner]) << (*supports)[inner].center.transpose();
    if (at.z() > -10) EXPECT_GT(f((*supports)[inner].center), 0.0);
  }
  EXPECT_GT(parents, 0);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
