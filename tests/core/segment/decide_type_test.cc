// NearlyFlat, the test behind the type decision's and FinalizeRegions' plane
// for a curved fit that bends less than the tolerances over its region. And
// TakesOverNearTheNoise, the rule by which RetypeByInterior and
// RetypeCoaxialBands weigh a type against a region's own.
#include "segment/decide_type.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::AllVertices;
using testing::BuildSheet;
using testing::Sheet;

// A quarter of a cylinder of radius 6 around the z axis, 20 long: the size
// of test_piece's rounds at h 1. th_dis 0.45 (3 sigma at 0.15 h), th_nm 10.
void BuildQuarterRound(Sheet* s) {
  BuildSheet(
      [](double phi, double z) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        return std::pair{Eigen::Vector3d(6.0 * radial + z * Eigen::Vector3d::UnitZ()), radial};
      },
      0.0, std::numbers::pi / 2, 10, -10.0, 10.0, 21, /*distance=*/0.45, /*angle_deg=*/10.0, s);
}

TEST(NearlyFlatTest, TorusAlongARoundAtItsInnerEquatorIsNot) {
  // The torus a fit gave test_piece's round at 0.15 h (seed 88): a tube far
  // larger than the round, whose inner equator, R - r = 6 from the axis,
  // bends like the round. Its tube radius alone said "flat", and the round
  // became a plane missing it by 3.8 sigma.
  Sheet s;
  BuildQuarterRound(&s);
  const Torus torus{.center = Eigen::Vector3d::Zero(),
                    .axis_direction = Eigen::Vector3d::UnitZ(),
                    .major_radius = 1253.0,
                    .minor_radius = 1247.0};
  EXPECT_FALSE(NearlyFlat(s.c, torus, /*rms=*/0.05, AllVertices(s), s.c.tolerance));
  const Cylinder cylinder{.axis_origin = Eigen::Vector3d::Zero(),
                          .axis_direction = Eigen::Vector3d::UnitZ(),
                          .radius = 6.0};
  EXPECT_FALSE(NearlyFlat(s.c, cylinder, /*rms=*/0.0, AllVertices(s), s.c.tolerance));
}

TEST(NearlyFlatTest, HugeCylinderAlongAFlatSideIsFlat) {
  // plate_boss's side at 0.15 h (seed 92): 60 long, 10 high, grown as a
  // cylinder of r 572 whose axis runs along it. Across the axis it bends by
  // 5^2 / 1144 = 0.02; along it, not at all (30^2 / 1144 = 0.79 would say
  // curved).
  Sheet s;
  testing::BuildFlatSide(&s);
  const Cylinder cylinder{.axis_origin = Eigen::Vector3d(0.0, 572.0, 0.0),
                          .axis_direction = Eigen::Vector3d::UnitX(),
                          .radius = 572.0};
  EXPECT_TRUE(NearlyFlat(s.c, cylinder, /*rms=*/0.075, AllVertices(s), s.c.tolerance));
}

TEST(NearlyFlatTest, TorusLargeBothWaysIsFlat) {
  // The same patch size on the outer equator of a torus of radii 2000 and
  // 1000: both principal radii are over 1000.
  Sheet s;
  BuildSheet(
      [](double y, double z) {
        const double x = std::sqrt(3000.0 * 3000.0 - y * y);
        return std::pair{Eigen::Vector3d(x, y, z), Eigen::Vector3d(x, y, 0.0).normalized()};
      },
      -4.0, 4.0, 10, -10.0, 10.0, 21, /*distance=*/0.45, /*angle_deg=*/10.0, &s);
  const Torus torus{.center = Eigen::Vector3d::Zero(),
                    .axis_direction = Eigen::Vector3d::UnitZ(),
                    .major_radius = 2000.0,
                    .minor_radius = 1000.0};
  EXPECT_TRUE(NearlyFlat(s.c, torus, /*rms=*/0.0, AllVertices(s), s.c.tolerance));
}

TEST(TakesOverNearTheNoiseTest, ALimitNeedsOnlyToScoreWithinTheMarginAbove) {
  SegmentContext c;
  c.noise_sigma = 0.1;
  const double near = kScoredNearError * c.noise_sigma;
  // A cone (a limit of the torus) 9 above it; a sphere (not one) 9 below.
  EXPECT_TRUE(
      TakesOverNearTheNoise(c, SurfaceType::kCone, near, -91.0, SurfaceType::kTorus, -100.0));
  EXPECT_FALSE(
      TakesOverNearTheNoise(c, SurfaceType::kSphere, near, -109.0, SurfaceType::kTorus, -100.0));
  EXPECT_TRUE(
      TakesOverNearTheNoise(c, SurfaceType::kSphere, near, -111.0, SurfaceType::kTorus, -100.0));
  // Past kScoredNearError sigmas nothing takes over, however it scores.
  EXPECT_FALSE(TakesOverNearTheNoise(c, SurfaceType::kCone, 1.01 * near, -200.0,
                                     SurfaceType::kTorus, -100.0));
  // A region whose own type has no valid fit (score infinite) gives way.
  EXPECT_TRUE(TakesOverNearTheNoise(c, SurfaceType::kSphere, near, -50.0, SurfaceType::kTorus,
                                    std::numeric_limits<double>::infinity()));
}

}  // namespace
}  // namespace meshseg::segment_internal
