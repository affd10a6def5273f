#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

test::Samples PlanePatch(double sigma) {
  const Eigen::Matrix3d r = test::Tilt();
  return test::SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        *p = Eigen::Vector3d(1, 2, 3) + r * Eigen::Vector3d(4 * s, 3 * t, 0);
        *n = r.col(2);
      },
      12, 10, sigma);
}

TEST(FitPlane, RecoversExactPlane) {
  const test::Samples s = PlanePatch(0.0);
  const FitResult r = FitPlane(s.Input());
  ASSERT_TRUE(r.ok());
  const auto& pl = std::get<Plane>(r.surface);
  EXPECT_GT(pl.normal.dot(test::Tilt().col(2)), 1.0 - 1e-12);  // oriented like the normals
  EXPECT_NEAR((pl.point - Eigen::Vector3d(1, 2, 3)).dot(pl.normal), 0.0, 1e-9);
  EXPECT_LT(r.rms_distance, 1e-9);
  EXPECT_LT(r.max_distance, 1e-9);
}

TEST(FitPlane, NoisyPlaneNormalWithinTolerance) {
  constexpr double kSigma = 0.01;
  const test::Samples s = PlanePatch(kSigma);
  const FitResult r = FitPlane(s.Input());
  ASSERT_TRUE(r.ok());
  const auto& pl = std::get<Plane>(r.surface);
  EXPECT_LT(test::AxisAngle(pl.normal, test::Tilt().col(2)), 0.1 * M_PI / 180.0);  // 0.1 deg
  EXPECT_NEAR(r.rms_distance, kSigma, 0.3 * kSigma);
  EXPECT_GE(r.max_distance, r.rms_distance);
}

TEST(FitPlane, FastFitUsesMeanNormal) {
  const test::Samples s = PlanePatch(0.0);
  const FitResult r = FitPlane(s.Input(), FitParams{.refine = false});
  ASSERT_TRUE(r.ok());
  EXPECT_GT(std::get<Plane>(r.surface).normal.dot(test::Tilt().col(2)), 1.0 - 1e-12);
}

TEST(FitPlane, DegenerateInputIsInvalidAndFinite) {
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  for (const auto* pts : {&two, &line}) {
    const FitResult r = FitPlane(FitInput{*pts, {}, {}});
    EXPECT_FALSE(r.ok());
    const auto& pl = std::get<Plane>(r.surface);
    EXPECT_TRUE(pl.point.allFinite() && pl.normal.allFinite());
    EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
  }
  EXPECT_FALSE(FitPlane(FitInput{}).ok());
}

TEST(FitPlane, NonFinitePointIsInvalid) {
  test::Samples s = test::SampleTorus(Torus{}, M_PI, 0.0, M_PI, 8, 6, 0.0);
  s.points[5].x() = std::numeric_limits<double>::quiet_NaN();
  const FitResult r = FitPlane(s.Input());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
}

}  // namespace
}  // namespace meshseg
