#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

const Torus kTrue{Eigen::Vector3d(1.0, 0.5, -2.0), test::Tilt().col(0), 4.0, 1.0};
constexpr double kExactTol = 1e-6;
constexpr double kSigma = 0.02;

void ExpectTorus(const FitResult& r, double radius_tol, double centre_tol, double axis_tol) {
  ASSERT_TRUE(r.ok());
  const auto& t = std::get<Torus>(r.surface);
  EXPECT_NEAR(t.major_radius, kTrue.major_radius, radius_tol);
  EXPECT_NEAR(t.minor_radius, kTrue.minor_radius, radius_tol);
  EXPECT_LT((t.center - kTrue.center).norm(), centre_tol);
  EXPECT_LT(test::AxisAngle(t.axis_direction, kTrue.axis_direction), axis_tol);
}

TEST(FitTorus, RecoversExactFullTorusAndPatch) {
  // Full torus; and a fillet-like patch: a quarter turn, outer half of the tube.
  const test::Samples full = test::SampleTorus(kTrue, 2 * M_PI, 0.0, 2 * M_PI, 24, 12, 0.0);
  ExpectTorus(FitTorus(full.Input()), kExactTol, kExactTol, kExactTol);
  const test::Samples patch = test::SampleTorus(kTrue, M_PI / 2, -M_PI / 2, M_PI / 2, 16, 12, 0.0);
  const FitResult r = FitTorus(patch.Input());
  ExpectTorus(r, kExactTol, kExactTol, kExactTol);
  EXPECT_LT(r.max_distance, kExactTol);
}

TEST(FitTorus, RecoversRadiiOnNoisyPatch) {
  // 192 points, quarter turn, outer half tube: radii within 1 sigma, centre
  // within 1.5 sigma, axis within 0.3 deg (measured 0.6 sigma, 0.5 sigma,
  // 0.12 deg).
  const test::Samples s = test::SampleTorus(kTrue, M_PI / 2, -M_PI / 2, M_PI / 2, 16, 12, kSigma);
  const FitResult r = FitTorus(s.Input());
  ExpectTorus(r, 1 * kSigma, 1.5 * kSigma, 0.3 * M_PI / 180);
  EXPECT_NEAR(r.rms_distance, kSigma, 0.3 * kSigma);
}

TEST(FitTorus, RefinementImprovesLinearInit) {
  const test::Samples s = test::SampleTorus(kTrue, M_PI / 2, -M_PI / 2, M_PI / 2, 16, 12, 5 * kSigma);
  const FitResult init = FitTorus(s.Input(), FitParams{.refine = false});
  const FitResult refined = FitTorus(s.Input());
  ASSERT_TRUE(init.ok() && refined.ok());
  EXPECT_GT(refined.iterations, 0);
  EXPECT_LT(refined.rms_distance, init.rms_distance);
}

TEST(FitTorus, DegenerateInputIsInvalidAndFinite) {
  const test::Samples s = test::SampleTorus(kTrue, M_PI / 2, -M_PI / 2, M_PI / 2, 16, 12, 0.0);
  std::vector<Eigen::Vector3d> line, up;
  for (int i = 0; i < 10; ++i) {
    line.emplace_back(i, 2 * i, 3 * i);
    up.emplace_back(0.0, 0.0, 1.0);
  }
  const FitResult cases[] = {
      FitTorus(s.PointsOnly()),
      FitTorus(FitInput{std::span(s.points).first(7), std::span(s.normals).first(7), {}}),
      FitTorus(FitInput{line, up, {}}),
  };
  for (const FitResult& r : cases) {
    EXPECT_FALSE(r.ok());
    const auto& t = std::get<Torus>(r.surface);
    EXPECT_TRUE(t.center.allFinite() && t.axis_direction.allFinite() &&
                std::isfinite(t.major_radius) && std::isfinite(t.minor_radius));
  }
}

TEST(FitTorus, NonFinitePointIsInvalid) {
  test::Samples s = test::SampleTorus(Torus{}, M_PI, 0.0, M_PI, 8, 6, 0.0);
  s.points[5].x() = std::numeric_limits<double>::quiet_NaN();
  const FitResult r = FitTorus(s.Input());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
}

}  // namespace
}  // namespace meshseg
