#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

// A bore of radius 8 along the tilted z axis from h = 0 to 18, and a
// 45-degree countersink opening from it at h = 18 to radius 10.5 (the
// shape of test_piece's).
const Eigen::Vector3d kOrigin(1.0, -2.0, 0.5);
Eigen::Vector3d Axis() { return test::Tilt() * Eigen::Vector3d::UnitZ(); }
Cylinder Bore() { return {kOrigin, Axis(), 8.0}; }
Cone Countersink() { return {kOrigin + 10.0 * Axis(), Axis(), M_PI / 4}; }

test::Samples BoreSamples(double sigma) {
  return test::SampleCylinder(Bore(), 2 * M_PI, 18.0, 120, 40, sigma, 3);
}
// Generators from distance 8 sqrt(2) (radius 8) to 10.5 sqrt(2): 3 rows of
// 60, a narrow band.
test::Samples CountersinkSamples(double sigma) {
  return test::SampleCone(Countersink(), 2 * M_PI, 8.0 * M_SQRT2, 10.5 * M_SQRT2, 60, 3, sigma, 5);
}

double AxisErrorDeg(const Surface& s) {
  const Eigen::Vector3d a = std::holds_alternative<Cone>(s) ? std::get<Cone>(s).axis_direction
                                                            : std::get<Cylinder>(s).axis_direction;
  return test::AxisAngle(a, Axis()) * 180.0 / M_PI;
}

TEST(FitCoaxial, RecoversBoreAndCountersinkExactly) {
  const test::Samples bore = BoreSamples(0.0);
  const test::Samples sink = CountersinkSamples(0.0);
  const std::vector<CoaxialMember> members = {{SurfaceType::kCylinder, bore.PointsOnly()},
                                              {SurfaceType::kCone, sink.PointsOnly()}};
  // Start 2 degrees and 0.3 off.
  const Eigen::Vector3d start_axis = test::Tilt() * Eigen::Vector3d(0.035, 0.0, 1.0);
  const std::vector<FitResult> fits =
      FitCoaxial(members, kOrigin + Eigen::Vector3d(0.3, 0.0, 0.0), start_axis);
  ASSERT_EQ(fits.size(), 2u);
  ASSERT_TRUE(fits[0].ok() && fits[1].ok());
  const Cylinder& cyl = std::get<Cylinder>(fits[0].surface);
  const Cone& cone = std::get<Cone>(fits[1].surface);
  EXPECT_NEAR(cyl.radius, 8.0, 1e-9);
  EXPECT_LT(test::DistanceToLine(cyl.axis_origin, kOrigin, Axis()), 1e-9);
  EXPECT_NEAR(cone.half_angle, M_PI / 4, 1e-9);
  EXPECT_LT((cone.apex - Countersink().apex).norm(), 1e-8);
  EXPECT_GT(cone.axis_direction.dot(Axis()), 1.0 - 1e-12);  // apex -> opening
  EXPECT_LT(fits[0].rms_distance, 1e-9);
  EXPECT_LT(fits[1].rms_distance, 1e-9);
}

// The point of fitting them together: the narrow band alone gets its axis
// from little data; with the bore it gets the bore's (noise 0.15 on both).
TEST(FitCoaxial, NarrowConeTakesTheBoresAxis) {
  const double sigma = 0.15;
  const test::Samples bore = BoreSamples(sigma);
  const test::Samples sink = CountersinkSamples(sigma);
  const FitResult alone = FitCone(sink.PointsOnly());
  ASSERT_TRUE(alone.ok());
  const std::vector<CoaxialMember> members = {{SurfaceType::kCylinder, bore.PointsOnly()},
                                              {SurfaceType::kCone, sink.PointsOnly()}};
  const std::vector<FitResult> fits = FitCoaxial(members, kOrigin, Axis());
  ASSERT_TRUE(fits[0].ok() && fits[1].ok());
  const double alone_deg = AxisErrorDeg(alone.surface);
  const double joint_deg = AxisErrorDeg(fits[1].surface);
  EXPECT_GT(alone_deg, 1.0);   // 2.16 with these samples
  EXPECT_LT(joint_deg, 0.05);  // 0.015
  EXPECT_NEAR(std::get<Cone>(fits[1].surface).half_angle, M_PI / 4, 1.0 * M_PI / 180);  // 0.75
  // The joint fit misses the band by little more than its own fit does.
  EXPECT_LT(fits[1].rms_distance, 1.05 * alone.rms_distance);
}

TEST(FitCoaxial, OneMemberIsTheCylinderFit) {
  const test::Samples bore = BoreSamples(0.05);
  const std::vector<CoaxialMember> members = {{SurfaceType::kCylinder, bore.PointsOnly()}};
  const std::vector<FitResult> fits =
      FitCoaxial(members, kOrigin, test::Tilt() * Eigen::Vector3d(0.02, 0.0, 1.0));
  const FitResult alone = FitCylinder(bore.Input());
  ASSERT_TRUE(fits[0].ok() && alone.ok());
  EXPECT_NEAR(fits[0].rms_distance, alone.rms_distance, 1e-9);
  EXPECT_NEAR(std::get<Cylinder>(fits[0].surface).radius, std::get<Cylinder>(alone.surface).radius,
              1e-7);
}

TEST(FitCoaxial, OtherTypesAndTooFewPointsAreInvalid) {
  const test::Samples bore = BoreSamples(0.0);
  const test::Samples sink = CountersinkSamples(0.0);
  std::vector<CoaxialMember> members = {{SurfaceType::kCylinder, bore.PointsOnly()},
                                        {SurfaceType::kSphere, sink.PointsOnly()}};
  std::vector<FitResult> fits = FitCoaxial(members, kOrigin, Axis());
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_FALSE(fits[0].ok() || fits[1].ok());

  const std::vector<Eigen::Vector3d> five(sink.points.begin(), sink.points.begin() + 5);
  members[1] = {SurfaceType::kCone, {.points = five, .normals = {}, .weights = {}}};
  fits = FitCoaxial(members, kOrigin, Axis());
  EXPECT_FALSE(fits[0].ok() || fits[1].ok());

  fits = FitCoaxial(std::vector<CoaxialMember>{{SurfaceType::kCylinder, bore.PointsOnly()}},
                    Eigen::Vector3d(NAN, 0, 0), Axis());
  EXPECT_FALSE(fits[0].ok());
}

// A cone on the axis of a cylinder fits as a cylinder's coaxial neighbour
// only as a cone: one whose points lie on a cylinder has no apex.
TEST(FitCoaxial, ConeMemberOnACylinderIsInvalid) {
  const test::Samples bore = BoreSamples(0.0);
  const test::Samples more =
      test::SampleCylinder({kOrigin + 20 * Axis(), Axis(), 5.0}, 2 * M_PI, 5.0, 40, 5, 0.0);
  const std::vector<CoaxialMember> members = {{SurfaceType::kCylinder, bore.PointsOnly()},
                                              {SurfaceType::kCone, more.PointsOnly()}};
  const std::vector<FitResult> fits = FitCoaxial(members, kOrigin, Axis());
  EXPECT_FALSE(fits[0].ok() || fits[1].ok());
}

}  // namespace
}  // namespace meshseg
