#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

const Cylinder kTrue{Eigen::Vector3d(1.0, 2.0, -1.0), test::Tilt().col(2), 3.0};
constexpr double kExactTol = 1e-6;
constexpr double kSigma = 0.02;  // noise along the normal, model units (R = 3)

struct ArcCase {
  const char* name;
  double arc;
  double radius_tol;  // for noise kSigma, in multiples of kSigma
};

void ExpectCylinder(const FitResult& r, double radius_tol, double axis_tol_rad,
                    double origin_tol) {
  ASSERT_TRUE(r.ok());
  const auto& c = std::get<Cylinder>(r.surface);
  EXPECT_NEAR(c.radius, kTrue.radius, radius_tol);
  EXPECT_LT(test::AxisAngle(c.axis_direction, kTrue.axis_direction), axis_tol_rad);
  EXPECT_LT(test::DistanceToLine(c.axis_origin, kTrue.axis_origin, kTrue.axis_direction),
            origin_tol);
  EXPECT_NEAR(c.axis_direction.norm(), 1.0, 1e-12);
}

TEST(FitCylinder, RecoversExactArcs) {
  for (const double arc : {2 * M_PI, M_PI, M_PI / 2}) {
    SCOPED_TRACE(arc);
    const test::Samples s = test::SampleCylinder(kTrue, arc, 6.0, 24, 10, 0.0);
    const FitResult r = FitCylinder(s.Input());
    ExpectCylinder(r, kExactTol, kExactTol, kExactTol);
    EXPECT_LT(r.max_distance, kExactTol);
  }
}

TEST(FitCylinder, RecoversRadiusOnNoisyArcs) {
  // 240 points, sigma = 0.02: full / half / quarter arc radius errors
  // within 0.25 / 0.25 / 1 sigma (measured 0.08 / 0.01 / 0.3), axis within
  // 0.5 deg (measured <= 0.1), axis position within 2 sigma. The quarter arc
  // is the hardest, as in seed 000's test piece.
  const ArcCase cases[] = {{"full", 2 * M_PI, 0.25}, {"half", M_PI, 0.25}, {"quarter", M_PI / 2, 1.0}};
  for (const ArcCase& c : cases) {
    SCOPED_TRACE(c.name);
    const test::Samples s = test::SampleCylinder(kTrue, c.arc, 6.0, 24, 10, kSigma);
    const FitResult r = FitCylinder(s.Input());
    ExpectCylinder(r, c.radius_tol * kSigma, 0.5 * M_PI / 180, 2 * kSigma);
    EXPECT_NEAR(r.rms_distance, kSigma, 0.3 * kSigma);
  }
}

TEST(FitCylinder, RefinementImprovesLinearInit) {
  // Noisy normals spoil the Gauss-sphere axis; the geometric fit recovers it.
  test::Samples s = test::SampleCylinder(kTrue, M_PI / 2, 6.0, 24, 10, kSigma);
  for (std::size_t i = 0; i < s.normals.size(); ++i) {
    s.normals[i] = (s.normals[i] + 0.05 * Eigen::Vector3d(std::sin(7.0 * i), std::cos(3.0 * i),
                                                          std::sin(5.0 * i + 1)))
                       .normalized();
  }
  const FitResult init = FitCylinder(s.Input(), FitParams{.refine = false});
  const FitResult refined = FitCylinder(s.Input());
  ASSERT_TRUE(init.ok() && refined.ok());
  EXPECT_GT(refined.iterations, 0);
  EXPECT_LT(refined.rms_distance, init.rms_distance);
  EXPECT_NEAR(std::get<Cylinder>(refined.surface).radius, kTrue.radius, 4 * kSigma);
}

TEST(FitCylinder, NarrowArcWithNormalsScatteredAlongTheAxisFindsTheAxis) {
  // A long 40-degree strip (15 along the axis, 2.1 across) whose normals
  // scatter along the axis about as much as they fan out across the arc: on
  // the Gauss sphere the axis no longer has the smallest spread. The middle
  // of a radius-4 round at 0.15 h looked like this (spreads 0.035 across,
  // 0.043 along) and fitted r 2077 with the across direction as its axis;
  // this one fitted r 4946 before the second start.
  test::Samples s = test::SampleCylinder(kTrue, 40.0 * M_PI / 180, 15.0, 8, 50, 2.5 * kSigma);
  for (std::size_t i = 0; i < s.normals.size(); ++i) {
    const double along = 0.3 * std::sin(7.0 * i + 0.3);
    s.normals[i] = (s.normals[i] + along * kTrue.axis_direction).normalized();
  }
  const FitResult r = FitCylinder(s.Input());
  ExpectCylinder(r, 0.1 * kTrue.radius, 2.0 * M_PI / 180, 0.1 * kTrue.radius);
  EXPECT_LT(r.rms_distance, 1.2 * 2.5 * kSigma);
}

TEST(FitCylinder, NarrowArcWithNormalsScatteredAslantFindsTheAxis) {
  // A 30-degree strip, 15 along the axis, whose normals scatter along a
  // direction 22 degrees off the axis: the Gauss sphere's two small
  // directions are both well off the axis, and from either the fit went to
  // r 3725. The strip's own long direction is tried too. rounded_prism at
  // 0.15 h (seed 77) had such a band of an r 4 round: the two directions 22
  // and 68 degrees off the axis, the long one 1.5; fitted r 469.
  test::Samples s = test::SampleCylinder(kTrue, 30.0 * M_PI / 180, 15.0, 8, 50, 2.5 * kSigma);
  const Eigen::Vector3d across = kTrue.axis_direction.cross(s.normals[s.normals.size() / 2]);
  const double tilt = 22.0 * M_PI / 180;
  const Eigen::Vector3d aslant = std::cos(tilt) * kTrue.axis_direction + std::sin(tilt) * across;
  for (std::size_t i = 0; i < s.normals.size(); ++i) {
    s.normals[i] = (s.normals[i] + 0.2 * std::sin(7.0 * i + 0.3) * aslant).normalized();
  }
  const FitResult r = FitCylinder(s.Input());
  ExpectCylinder(r, 0.1 * kTrue.radius, 2.0 * M_PI / 180, 0.1 * kTrue.radius);
}

TEST(FitCylinder, WorksWithoutNormals) {
  const test::Samples s = test::SampleCylinder(kTrue, M_PI, 6.0, 24, 10, 0.0);
  ExpectCylinder(FitCylinder(s.PointsOnly()), kExactTol, kExactTol, kExactTol);
}

TEST(FitCylinder, DegenerateInputIsInvalidAndFinite) {
  std::vector<Eigen::Vector3d> line, plane, plane_normals;
  for (int i = 0; i < 10; ++i) line.emplace_back(i, 2 * i, 3 * i);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      plane.emplace_back(i, j, 0.0);
      plane_normals.emplace_back(0.0, 0.0, 1.0);
    }
  }
  const FitResult cases[] = {
      FitCylinder(FitInput{line, {}, {}}),
      FitCylinder(FitInput{plane, {}, {}}),
      FitCylinder(FitInput{plane, plane_normals, {}}),
      FitCylinder(FitInput{std::span(plane).first(4), {}, {}}),
  };
  for (const FitResult& r : cases) {
    EXPECT_FALSE(r.ok());
    const auto& c = std::get<Cylinder>(r.surface);
    EXPECT_TRUE(c.axis_origin.allFinite() && c.axis_direction.allFinite() && std::isfinite(c.radius));
    EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
  }
}

TEST(FitCylinder, NonFinitePointIsInvalid) {
  test::Samples s = test::SampleTorus(Torus{}, M_PI, 0.0, M_PI, 8, 6, 0.0);
  s.points[5].x() = std::numeric_limits<double>::quiet_NaN();
  const FitResult r = FitCylinder(s.Input());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(std::isfinite(r.rms_distance) && std::isfinite(r.max_distance));
}

}  // namespace
}  // namespace meshseg
