#include "topology/fit_curve.h"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::topology_internal {
namespace {

TEST(FitCircle, RecoversANoisyArc) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.1 * i;  // a 2-radian arc of radius 5 in the plane z = 1
    points.push_back({5.0 * std::cos(t) + noise(rng), 5.0 * std::sin(t) + noise(rng), 1.0});
  }
  const auto g = FitCircle(points);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->radius, 5.0, 0.05);
  EXPECT_NEAR((g->point - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 0.05);
  EXPECT_NEAR(std::abs(g->direction.z()), 1.0, 1e-3);
  EXPECT_LT(MaxDeviation(*g, points), 0.05);
}

TEST(FitCircle, CollinearPointsHaveNoCircle) {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_FALSE(FitCircle(points).has_value());
  const auto line = FitLine(points);
  ASSERT_TRUE(line.has_value());
  EXPECT_NEAR(std::abs(line->direction.dot(Eigen::Vector3d(1, 1, 1).normalized())), 1.0, 1e-12);
  EXPECT_NEAR(MaxDeviation(*line, points), 0.0, 1e-12);
}

TEST(MaxDeviation, MeasuresDistanceFromTheCircleIn3d) {
  CurveGeometry g;
  g.type = CurveGeometryType::kCircle;
  g.radius = 2.0;
  const std::vector<Eigen::Vector3d> points = {{2, 0, 0}, {0, 3, 0}, {2, 0, 1}};
  EXPECT_NEAR(MaxDeviation(g, points), 1.0, 1e-12);
}

}  // namespace
}  // namespace meshseg::topology_internal
