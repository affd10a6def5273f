#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
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

// z = 0.1 x^2 - 0.2 y^2 + 0.3 x + 0.5 on 40 points around the unit circle,
// the radius varied by `ripple` sin(7 t). On the circle (ripple 0) the
// columns u^2, w^2 and 1 of the normal equations are dependent, so the
// height function is not determined.
std::vector<Eigen::Vector3d> AroundCircle(double ripple) {
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 40; ++k) {
    const double t = 2.0 * M_PI * k / 40.0;
    const double r = 1.0 + ripple * std::sin(7.0 * t);
    const double x = r * std::cos(t), y = r * std::sin(t);
    pts.emplace_back(x, y, 0.1 * x * x - 0.2 * y * y + 0.3 * x + 0.5);
  }
  return pts;
}

// Smallest / largest eigenvalue of the normal equations FitHeightFunction
// solves (u, w at unit RMS) for points given in the frame's coordinates.
double EigenvalueRatio(const std::vector<Eigen::Vector3d>& pts) {
  double r2 = 0.0;
  for (const auto& p : pts) r2 += p.x() * p.x() + p.y() * p.y();
  const double s = std::sqrt(r2 / pts.size());
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  for (const auto& p : pts) {
    const double u = p.x() / s, w = p.y() / s;
    Eigen::Matrix<double, 6, 1> phi;
    phi << u * u, w * w, u * w, u, w, 1.0;
    m += phi * phi.transpose();
  }
  const Eigen::Matrix<double, 6, 1> ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(m).eigenvalues();
  return ev(0) / ev(5);
}

TEST(FitHeightFunction, PointsOnACircleAreSingular) {
  const auto pts = AroundCircle(0.0);
  ASSERT_LT(EigenvalueRatio(pts), 1e-12);
  EXPECT_FALSE(FitHeightFunction(pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()).valid);
}

// Near the singularity limit (eigenvalue ratio 1e-10) but above it, the
// fit is made and exact: the data lie on a quadratic, so any backward
// stable solve of a system of condition ~1e8 reproduces it to ~1e-8.
TEST(FitHeightFunction, NearlySingularButAboveTheLimitFitsExactly) {
  const auto pts = AroundCircle(3e-4);
  const double ratio = EigenvalueRatio(pts);
  ASSERT_GT(ratio, 1e-10);
  ASSERT_LT(ratio, 1e-6);
  HeightFunction h;
  ASSERT_TRUE(HeightFrame(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), &h));
  FitHeightInFrame(pts, {}, &h);  // the frame's own coordinates
  ASSERT_TRUE(h.valid);
  const std::array<double, 6> want = {0.1, -0.2, 0.0, 0.3, 0.0, 0.5};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(h.a[i], want[i], 1e-6) << i;
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

// The two halves give FitHeightFunction's result bit for bit (the local
// curvature fit relies on it: same sums in the same order), on a tilted,
// noisy, weighted sample.
TEST(FitHeightInFrame, EqualsFitHeightFunctionBitForBit) {
  std::vector<Eigen::Vector3d> pts = QuadraticGraph();
  std::vector<double> w;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts[i] += Eigen::Vector3d(0.3, -0.2, 0.1) * std::sin(1.7 * i) * 1e-3;
    w.push_back(1.0 + 0.5 * std::cos(0.9 * i));
  }
  const Eigen::Vector3d origin = pts[3];
  const Eigen::Vector3d normal(0.2, -0.1, 0.97);
  const HeightFunction whole = FitHeightFunction(pts, origin, normal, w);
  HeightFunction h;
  ASSERT_TRUE(HeightFrame(origin, normal, &h));
  std::vector<Eigen::Vector3d> local;
  for (const Eigen::Vector3d& p : pts) {
    const Eigen::Vector3d d = p - origin;
    local.emplace_back(d.dot(h.u_axis), d.dot(h.w_axis), d.dot(h.normal));
  }
  FitHeightInFrame(local, w, &h);
  ASSERT_TRUE(whole.valid);
  ASSERT_TRUE(h.valid);
  EXPECT_EQ(h.normal, whole.normal);
  EXPECT_EQ(h.u_axis, whole.u_axis);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(h.a[k], whole.a[k]) << "coefficient " << k;
}

TEST(FitHeightInFrame, ZeroNormalOrFewPointsIsInvalid) {
  HeightFunction h;
  EXPECT_FALSE(HeightFrame(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), &h));
  EXPECT_FALSE(h.valid);
  ASSERT_TRUE(HeightFrame(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), &h));
  const std::vector<Eigen::Vector3d> five(5, Eigen::Vector3d(1.0, 2.0, 0.0));
  FitHeightInFrame(five, {}, &h);
  EXPECT_FALSE(h.valid);
}

}  // namespace
}  // namespace meshseg
