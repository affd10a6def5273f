#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

const Sphere kTrue{Eigen::Vector3d(1.0, -2.0, 0.5), 5.0};
constexpr double kExactTol = 1e-6;
constexpr double kSigma = 0.02;  // noise along the normal, model units

TEST(FitSphere, RecoversExactHemisphere) {
  const test::Samples s = test::SampleSphere(kTrue, test::Tilt().col(2), M_PI / 2, 10, 20, 0.0);
  const FitResult r = FitSphere(s.PointsOnly());
  ASSERT_TRUE(r.ok());
  const auto& sp = std::get<Sphere>(r.surface);
  EXPECT_NEAR(sp.radius, kTrue.radius, kExactTol);
  EXPECT_LT((sp.center - kTrue.center).norm(), kExactTol);
  EXPECT_LT(r.max_distance, kExactTol);
}

TEST(FitSphere, RecoversRadiusOnNoisyCap) {
  // 40 deg cap, 300 points: radius within 0.5 sigma, centre within 1 sigma
  // (measured 0.17 and 0.47 sigma).
  const test::Samples s = test::SampleSphere(kTrue, test::Tilt().col(2), 0.7, 15, 20, kSigma);
  const FitResult r = FitSphere(s.PointsOnly());
  ASSERT_TRUE(r.ok());
  const auto& sp = std::get<Sphere>(r.surface);
  EXPECT_NEAR(sp.radius, kTrue.radius, 0.5 * kSigma);
  EXPECT_LT((sp.center - kTrue.center).norm(), 1.0 * kSigma);
  EXPECT_NEAR(r.rms_distance, kSigma, 0.3 * kSigma);
}

TEST(FitSphere, RefinementDoesNotIncreaseRms) {
  const test::Samples s = test::SampleSphere(kTrue, test::Tilt().col(2), 0.5, 15, 20, 5 * kSigma);
  const FitResult init = FitSphere(s.PointsOnly(), FitParams{.refine = false});
  const FitResult refined = FitSphere(s.PointsOnly());
  ASSERT_TRUE(init.ok() && refined.ok());
  EXPECT_EQ(init.iterations, 0);
  EXPECT_GT(refined.iterations, 0);
  EXPECT_LE(refined.rms_distance, init.rms_distance);
}

TEST(FitSphere, DegenerateInputIsInvalidAndFinite) {
  std::vector<Eigen::Vector3d> planar;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) planar.emplace_back(i, j, 0.0);
  std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const auto* pts : {&planar, &three}) {
    const FitResult r = FitSphere(FitInput{*pts, {}, {}});
    EXPECT_FALSE(r.ok());
    const auto& sp = std::get<Sphere>(r.surface);
    EXPECT_TRUE(sp.center.allFinite() && std::isfinite(sp.radius));
    EXPECT_TRUE(std::isfinite(r.rms_distance));
  }
}

TEST(FitSphere, NonFinitePointIsInvalid) {
  test::Samples s = test::SampleTorus(Torus{}, M_PI, 0.0, M_PI, 8, 6, 0.0);
  s.points[5].x() = std::numeric_limits<double>::quiet_NaN();
  const FitResult r = FitSphere(s.Input());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
}

}  // namespace
}  // namespace meshseg
