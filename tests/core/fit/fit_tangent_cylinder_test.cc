#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

// A convex edge of a tilted block rounded with radius kRadius: faces a and
// b, outward normals na and nb `between_deg` apart, meeting along the line
// through kEdgePoint with direction na x nb. The round's axis lies inside,
// kRadius from both faces, on the side opposite both normals.
constexpr double kRadius = 4.0;
const Eigen::Vector3d kEdgePoint(2.0, -1.0, 3.0);

struct Corner {
  Plane a, b;
  Cylinder round;
};

Corner MakeCorner(double between_deg) {
  const Eigen::Matrix3d tilt = test::Tilt();
  const double t = between_deg * M_PI / 180.0;
  const Eigen::Vector3d na = tilt * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d nb = tilt * Eigen::Vector3d(std::cos(t), std::sin(t), 0.0);
  const Eigen::Vector3d axis = na.cross(nb).normalized();
  // Solve na.x = -r, nb.x = -r (relative to the edge), x across the axis.
  Eigen::Matrix3d m;
  m << na.transpose(), nb.transpose(), axis.transpose();
  const Eigen::Vector3d centre =
      kEdgePoint + m.inverse() * Eigen::Vector3d(-kRadius, -kRadius, 0.0);
  return {Plane{kEdgePoint, na}, Plane{kEdgePoint, nb}, Cylinder{centre, axis, kRadius}};
}

// Points of the round from `from` to `to` of the way between its tangent
// lines on a and b (0 and 1 are the tangent lines), `rows` x 12 along
// the axis over a length of 10, with Gaussian noise `sigma` along the
// normal (mt19937 draw `seed`).
test::Samples SampleRound(const Corner& c, double from, double to, int rows, double sigma,
                          unsigned seed = 7) {
  const Eigen::Vector3d na = c.a.normal, nb = c.b.normal;
  const double sweep = std::acos(na.dot(nb));
  const Eigen::Vector3d across = (nb - na.dot(nb) * na).normalized();
  return test::SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double phi = (from + s * (to - from)) * sweep;
        *n = std::cos(phi) * na + std::sin(phi) * across;
        *p = c.round.axis_origin + (t - 0.5) * 10.0 * c.round.axis_direction + kRadius * *n;
      },
      rows, 12, sigma, seed);
}

constexpr std::array<int, 2> kInside = {-1, -1};

TEST(FitCylinderTangentToPlanes, RecoversExactRounds) {
  for (const double between : {90.0, 45.0, 135.0}) {
    SCOPED_TRACE(between);
    const Corner c = MakeCorner(between);
    const test::Samples s = SampleRound(c, 0.0, 1.0, 9, 0.0);
    const FitResult r = FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, kInside, 3.0);
    ASSERT_TRUE(r.ok());
    const auto& got = std::get<Cylinder>(r.surface);
    EXPECT_NEAR(got.radius, kRadius, 1e-9);
    EXPECT_LT(test::AxisAngle(got.axis_direction, c.round.axis_direction), 1e-12);
    EXPECT_LT(test::DistanceToLine(got.axis_origin, c.round.axis_origin, c.round.axis_direction),
              1e-9);
    EXPECT_LT(r.max_distance, 1e-9);
  }
}

// The case the fit is for (rounded_prism at 0.15 h): a noisy quarter round
// of which only the middle 60 % is held by the round's region. Fitted
// alone, the narrow arc leaves the radius to the noise; tangent to the
// faces beside it, the radius is the one value the points must fix. Near
// the tangent lines a change of radius hardly moves the surface, so even
// then the error is a fair part of sigma.
TEST(FitCylinderTangentToPlanes, FixesTheRadiusOfANarrowNoisyArc) {
  const Corner c = MakeCorner(90.0);
  const double sigma = 0.05;  // 0.15 h at h = 1/3, as rounded_prism
  double free_worst = 0.0, tangent_worst = 0.0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    const test::Samples s = SampleRound(c, 0.2, 0.8, 12, sigma, seed);
    const FitResult free = FitCylinder(s.Input());
    const FitResult tangent = FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, kInside, 3.5);
    ASSERT_TRUE(free.ok());
    ASSERT_TRUE(tangent.ok());
    free_worst = std::max(free_worst, std::abs(std::get<Cylinder>(free.surface).radius - kRadius));
    tangent_worst =
        std::max(tangent_worst, std::abs(std::get<Cylinder>(tangent.surface).radius - kRadius));
    EXPECT_NEAR(tangent.rms_distance, sigma, 0.3 * sigma);
  }
  // Measured over the 10 draws: worst 0.43 sigma tangent, 4.5 sigma free.
  EXPECT_LT(tangent_worst, 0.6 * sigma);
  EXPECT_GT(free_worst, 5.0 * tangent_worst);
}

TEST(FitCylinderTangentToPlanes, ConvergesFromAFarRadius) {
  const Corner c = MakeCorner(90.0);
  const test::Samples s = SampleRound(c, 0.0, 1.0, 9, 0.0);
  for (const double start : {0.5, 40.0}) {
    SCOPED_TRACE(start);
    const FitResult r = FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, kInside, start);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(std::get<Cylinder>(r.surface).radius, kRadius, 1e-6);
  }
}

TEST(FitCylinderTangentToPlanes, DegenerateInputsAreInvalidWithoutNaN) {
  const Corner c = MakeCorner(90.0);
  const test::Samples s = SampleRound(c, 0.0, 1.0, 9, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector3d> one = {s.points[0]};
  const Plane parallel{c.a.point + Eigen::Vector3d(0.1, 0, 0), c.a.normal};
  const Plane nan_plane{Eigen::Vector3d(nan, 0, 0), c.b.normal};
  const FitResult results[] = {
      FitCylinderTangentToPlanes({one, {}, {}}, c.a, c.b, kInside, 3.0),
      FitCylinderTangentToPlanes(s.PointsOnly(), c.a, parallel, kInside, 3.0),
      FitCylinderTangentToPlanes(s.PointsOnly(), c.a, nan_plane, kInside, 3.0),
      FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, kInside, 0.0),
      FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, kInside, nan),
      FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, {0, 1}, 3.0),
  };
  for (const FitResult& r : results) {
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(std::isnan(r.rms_distance));
  }
}

// On the outer side of both faces every tangent cylinder lies away from
// the round's points; the radius runs down to zero and there is no fit.
TEST(FitCylinderTangentToPlanes, OnTheWrongSideThereIsNoFit) {
  const Corner c = MakeCorner(90.0);
  const test::Samples s = SampleRound(c, 0.0, 1.0, 9, 0.0);
  const FitResult r = FitCylinderTangentToPlanes(s.PointsOnly(), c.a, c.b, {1, 1}, 3.0);
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace meshseg
