#include "fit/algebraic_sphere.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::fit_internal {
namespace {

TEST(FitAlgebraicSphere, RecoversCircleFromQuarterArc) {
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.5 * M_PI * i / 10;
    pts.emplace_back(3.0 + 2.0 * std::cos(t), -1.0 + 2.0 * std::sin(t));
  }
  const auto c = FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(pts), {});
  ASSERT_TRUE(c.valid);
  EXPECT_LT((c.center - Eigen::Vector2d(3.0, -1.0)).norm(), 1e-12);
  EXPECT_NEAR(c.radius, 2.0, 1e-12);
}

TEST(FitAlgebraicSphere, ZeroWeightsIgnorePoints) {
  std::vector<Eigen::Vector2d> pts = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {5, 5}};
  const std::vector<double> w = {1, 1, 1, 1, 0};
  const auto c = FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(pts), w);
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.radius, 1.0, 1e-12);
}

TEST(FitAlgebraicSphere, CollinearOrTooFewIsInvalid) {
  const std::vector<Eigen::Vector2d> line = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const std::vector<Eigen::Vector2d> two = {{0, 0}, {1, 1}};
  EXPECT_FALSE(FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(line), {}).valid);
  EXPECT_FALSE(FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(two), {}).valid);
  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(FitAlgebraicSphere<3>(std::span<const Eigen::Vector3d>(same), {}).valid);
}

}  // namespace
}  // namespace meshseg::fit_internal
