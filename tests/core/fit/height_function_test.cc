#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

// z = 0.1 x² + 0.2 y² + 0.05 xy + 0.3 x - 0.1 y + 0.2 on a grid.
std::vector<Eigen::Vector3d> QuadraticGraph() {
  std::vector<Eigen::Vector3d> pts;
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) {
      const double x = 0.25 * i, y = 0.25 * j;
      pts.emplace_back(x, y, 0.1 * x * x + 0.2 * y * y + 0.05 * x * y + 0.3 * x - 0.1 * y + 0.2);
    }
  }
  return pts;
}

TEST(FitHeightFunction, ReproducesExactQuadratic) {
  const auto pts = QuadraticGraph();
  const HeightFunction h = FitHeightFunction(pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(h.valid);
  EXPECT_NEAR(h.normal.dot(h.u_axis.cross(h.w_axis)), 1.0, 1e-12);
  // Invariants under the (free) choice of u_axis in the tangent plane.
  EXPECT_NEAR(h.a[5], 0.2, 1e-12);
  EXPECT_NEAR(h.a[3] * h.a[3] + h.a[4] * h.a[4], 0.1, 1e-12);
  EXPECT_NEAR(h.a[0] + h.a[1], 0.3, 1e-12);
  for (const auto& p : pts) EXPECT_NEAR(Project(h, p).distance, 0.0, 1e-12);
}

TEST(FitHeightFunction, WeightsSelectPoints) {
  auto pts = QuadraticGraph();
  std::vector<double> w(pts.size(), 1.0);
  pts.push_back(Eigen::Vector3d(0, 0, 10));  // outlier with zero weight
  w.push_back(0.0);
  const HeightFunction h =
      FitHeightFunction(pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), w);
  ASSERT_TRUE(h.valid);
  EXPECT_NEAR(h.a[5], 0.2, 1e-12);
}

TEST(FitHeightFunction, DegenerateInputIsInvalid) {
  const auto pts = QuadraticGraph();
  const std::vector<Eigen::Vector3d> five(pts.begin(), pts.begin() + 5);
  EXPECT_FALSE(FitHeightFunction(five, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()).valid);
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 10; ++i) line.emplace_back(i, 2 * i, 0.1 * i * i);
  EXPECT_FALSE(FitHeightFunction(line, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()).valid);
  EXPECT_FALSE(FitHeightFunction(pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()).valid);
  const HeightFunction bad = FitHeightFunction(line, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  for (double a : bad.a) EXPECT_TRUE(std::isfinite(a));
}

TEST(ProjectHeightFunction, DistanceAlongNormal) {
  // z = 0.1 (x² + y²): points offset along the true normal.
  std::vector<Eigen::Vector3d> pts;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) pts.emplace_back(0.5 * i, 0.5 * j, 0.1 * 0.25 * (i * i + j * j));
  const HeightFunction h = FitHeightFunction(pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(h.valid);
  constexpr double kTol = 1e-4;
  for (const double x : {-1.0, 0.3, 1.2}) {
    const Eigen::Vector3d on(x, 0.5, 0.1 * (x * x + 0.25));
    const Eigen::Vector3d n = Eigen::Vector3d(-0.2 * x, -0.1, 1.0).normalized();
    for (const double d : {-0.1, 0.05, 0.1}) {
      const Projection pr = Project(h, on + d * n);
      EXPECT_NEAR(pr.distance, d, kTol) << x;
      EXPECT_LT((pr.point - on).norm(), kTol);
      EXPECT_LT((pr.normal - n).norm(), kTol);
    }
  }
}

}  // namespace
}  // namespace meshseg
