#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

constexpr double kA = 3.0, kB = 2.0, kC = 1.5;
const Eigen::Vector3d kCentre(1.0, -1.0, 0.5);

// Patch of the ellipsoid (x-c)²/a² + ... = 1: polar angle in [0.3, 1.5].
test::Samples EllipsoidPatch(double sigma) {
  return test::SamplePatch(
      [](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double th = 0.3 + 1.2 * s, ph = 2.0 * t;
        const Eigen::Vector3d d(kA * std::sin(th) * std::cos(ph), kB * std::sin(th) * std::sin(ph),
                                kC * std::cos(th));
        *p = kCentre + d;
        *n = Eigen::Vector3d(d.x() / (kA * kA), d.y() / (kB * kB), d.z() / (kC * kC)).normalized();
      },
      15, 15, sigma);
}

Eigen::Matrix<double, 10, 1> Coefficients(const Quadric& q) {
  return Eigen::Map<const Eigen::Matrix<double, 10, 1>>(q.c.data());
}

TEST(FitQuadric, RecoversExactEllipsoid) {
  const test::Samples s = EllipsoidPatch(0.0);
  const FitResult r = FitQuadric(s.Input());
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.max_distance, 1e-9);
  // True coefficients, up to scale.
  Quadric truth;
  const double ia = 1 / (kA * kA), ib = 1 / (kB * kB), ic = 1 / (kC * kC);
  truth.c = {ia, ib, ic, 0, 0, 0, -2 * ia * kCentre.x(), -2 * ib * kCentre.y(), -2 * ic * kCentre.z(),
             ia * kCentre.x() * kCentre.x() + ib * kCentre.y() * kCentre.y() +
                 ic * kCentre.z() * kCentre.z() - 1};
  const auto got = Coefficients(std::get<Quadric>(r.surface)).normalized();
  const auto want = Coefficients(truth).normalized();
  EXPECT_LT(std::min((got - want).norm(), (got + want).norm()), 1e-9);
}

TEST(FitQuadric, RefinementRemovesUnitGradientBias) {
  // Eq. (8) alone asks for |∇f| = 1, which an ellipsoid cannot give.
  const test::Samples s = EllipsoidPatch(0.0);
  const FitResult eq8 = FitQuadric(s.Input(), FitParams{.refine = false});
  const FitResult refined = FitQuadric(s.Input());
  ASSERT_TRUE(eq8.ok() && refined.ok());
  EXPECT_EQ(eq8.iterations, 0);
  EXPECT_GT(eq8.max_distance, 1e-3);
  EXPECT_LT(refined.max_distance, 1e-9);
}

TEST(FitQuadric, GradientIsNormalisedAndOriented) {
  const test::Samples s = EllipsoidPatch(0.0);
  const FitResult r = FitQuadric(s.Input());
  ASSERT_TRUE(r.ok());
  // f ≈ signed distance: the projection normal agrees with the data normals.
  for (std::size_t i = 0; i < s.points.size(); i += 17) {
    const Projection pr = Project(r.surface, s.points[i] + 0.01 * s.normals[i], s.normals[i]);
    EXPECT_GT(pr.normal.dot(s.normals[i]), 1.0 - 1e-9);
    EXPECT_NEAR(pr.distance, 0.01, 1e-6);
  }
}

TEST(FitQuadric, NoisyEllipsoidRmsNearNoise) {
  constexpr double kSigma = 0.01;
  const test::Samples s = EllipsoidPatch(kSigma);
  const FitResult r = FitQuadric(s.Input());
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.rms_distance, kSigma, 0.3 * kSigma);
}

TEST(FitQuadric, CylinderPatchMatchesCylinderDistance) {
  const Cylinder c{Eigen::Vector3d(1, 2, 3), test::Tilt().col(2), 2.0};
  const test::Samples s = test::SampleCylinder(c, M_PI, 4.0, 16, 10, 0.0);
  const std::vector<double> area(s.points.size(), 0.05);  // λ = total area
  const FitResult r = FitQuadric(FitInput{s.points, s.normals, area});
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.max_distance, 1e-9);
  for (std::size_t i = 0; i < s.points.size(); i += 13) {
    const Eigen::Vector3d p = s.points[i] + 0.1 * s.normals[i];
    EXPECT_NEAR(Project(r.surface, p, s.normals[i]).distance, SignedDistance(c, p), 1e-6);
  }
}

TEST(FitQuadric, PlanarRegionIsFinite) {
  const test::Samples s = test::SamplePatch(
      [](double u, double v, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        *p = test::Tilt() * Eigen::Vector3d(3 * u, 2 * v, 0.0);
        *n = test::Tilt().col(2);
      },
      8, 8, 0.0);
  const FitResult r = FitQuadric(s.Input());
  ASSERT_TRUE(r.ok());
  for (double c : std::get<Quadric>(r.surface).c) EXPECT_TRUE(std::isfinite(c));
  EXPECT_LT(r.max_distance, 1e-9);
}

TEST(FitQuadric, DegenerateInputIsInvalidAndFinite) {
  const test::Samples s = EllipsoidPatch(0.0);
  std::vector<Eigen::Vector3d> line(12), up(12, Eigen::Vector3d::UnitZ());
  for (int i = 0; i < 12; ++i) line[i] = Eigen::Vector3d(i, i, i);
  const FitResult cases[] = {
      FitQuadric(s.PointsOnly()),
      FitQuadric(FitInput{std::span(s.points).first(9), std::span(s.normals).first(9), {}}),
      FitQuadric(FitInput{line, up, {}}),
  };
  for (const FitResult& r : cases) {
    EXPECT_FALSE(r.ok());
    for (double c : std::get<Quadric>(r.surface).c) EXPECT_TRUE(std::isfinite(c));
  }
}

TEST(FitQuadric, NonFinitePointIsInvalid) {
  test::Samples s = test::SampleTorus(Torus{}, M_PI, 0.0, M_PI, 8, 6, 0.0);
  s.points[5].x() = std::numeric_limits<double>::quiet_NaN();
  const FitResult r = FitQuadric(s.Input());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
}

}  // namespace
}  // namespace meshseg
