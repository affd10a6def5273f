// The priced retype (RetypeIfLower) and the proposals that use it
// (RetypeBentPlanes, RetypeInaccurateCurved, RetypeToSimplerLimits) on
// sheets cut from cones, cylinders, a plane and a disc with the start of its
// edge round.
#include "segment/retype_regions.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <optional>
#include <numbers>
#include <variant>
#include <vector>

#include "segment/energy.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::RegionsFromLabels;
using testing::Sheet;

// Half a turn of a cone band (half-angle 30 degrees, axis z, apex at the
// origin) from 4 to 10 along the generator.
void ConeBand(Sheet* s) {
  const double half = std::numbers::pi / 6.0;
  BuildSheet(
      [&](double t, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d p =
            t * (std::sin(half) * radial + std::cos(half) * Eigen::Vector3d::UnitZ());
        const Eigen::Vector3d n =
            std::cos(half) * radial - std::sin(half) * Eigen::Vector3d::UnitZ();
        return std::pair{p, n};
      },
      4.0, 10.0, 31, 0.0, std::numbers::pi, 61, /*distance=*/0.15, /*angle_deg=*/5.0, s);
}

// A quarter turn of a cylinder of radius 5 about the z axis, 10 long.
void QuarterCylinder(Sheet* s) {
  BuildSheet(
      [](double phi, double z) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        return std::pair{Eigen::Vector3d(5.0 * radial + z * Eigen::Vector3d::UnitZ()), radial};
      },
      0.0, std::numbers::pi / 2.0, 41, 0.0, 10.0, 41, /*distance=*/0.15, /*angle_deg=*/5.0, s);
}

TEST(RetypeIfLowerTest, TheTypeOfTheSurfaceLowersETheOtherDoesNot) {
  Sheet s;
  ConeBand(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> sphere = RegionsFromLabels(s.c, labels, {SurfaceType::kSphere});
  std::vector<RegionState> cone = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});

  const SurfaceType to_cone[] = {SurfaceType::kCone}, to_sphere[] = {SurfaceType::kSphere};
  EXPECT_TRUE(RetypeIfLower(s.c, &sphere[0], to_cone));
  EXPECT_EQ(sphere[0].type, SurfaceType::kCone);
  EXPECT_FALSE(RetypeIfLower(s.c, &cone[0], to_sphere));
  EXPECT_EQ(cone[0].type, SurfaceType::kCone);
}

TEST(RetypeIfLowerTest, AStaleSurfaceIsNotWhatARetypeIsPricedAgainst) {
  // The cone moved 0.5 along its axis: every vertex misses it by more than
  // th_dis, so a sphere fitted to the band costs less than that surface,
  // but not less than the cone refitted.
  Sheet s;
  ConeBand(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});
  std::get<Cone>(regions[0].surface).apex += Eigen::Vector3d(0, 0, 0.5);
  const std::optional<Move> against_stale = RetypeDelta(s.c, regions[0], SurfaceType::kSphere);
  ASSERT_TRUE(against_stale.has_value());
  ASSERT_LT(against_stale->delta, 0.0);

  const SurfaceType to_sphere[] = {SurfaceType::kSphere};
  EXPECT_FALSE(RetypeIfLower(s.c, &regions[0], to_sphere));
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
}

TEST(RetypeBentPlanesTest, PlaneOverAnArcBecomesItsCylinder) {
  Sheet s;
  QuarterCylinder(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kPlane});

  EXPECT_EQ(RetypeBentPlanes(s.c, &regions), std::vector<int>{0});
  ASSERT_EQ(regions[0].type, SurfaceType::kCylinder);
  EXPECT_NEAR(std::get<Cylinder>(regions[0].surface).radius, 5.0, 1e-3);
}

TEST(RetypeInaccurateCurvedTest, SphereOnAConeBandBecomesACone) {
  Sheet s;
  ConeBand(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kSphere});
  const FitResult sphere = FitType(s.c, SurfaceType::kSphere, regions[0].vertices);
  ASSERT_GT(sphere.rms_distance, 0.01) << "the band must be long enough to tell a sphere";

  const std::vector<int> retyped = RetypeInaccurateCurved(s.c, &regions);
  ASSERT_EQ(retyped, std::vector<int>{0});
  ASSERT_EQ(regions[0].type, SurfaceType::kCone);
  EXPECT_NEAR(std::get<Cone>(regions[0].surface).half_angle, std::numbers::pi / 6.0, 1e-4);
}

TEST(RetypeInaccurateCurvedTest, ConeThatFitsStays) {
  Sheet s;
  ConeBand(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});
  EXPECT_TRUE(RetypeInaccurateCurved(s.c, &regions).empty());
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
}

TEST(RetypeInaccurateCurvedTest, SphereWithinTheNoiseStays) {
  // The same sphere on the cone band, where the noise is as large as the
  // sphere's miss: its model error is 0 and the cone has nothing to gain.
  Sheet s;
  ConeBand(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kSphere});
  s.c.noise_sigma = FitType(s.c, SurfaceType::kSphere, regions[0].vertices).rms_distance;
  EXPECT_TRUE(RetypeInaccurateCurved(s.c, &regions).empty());
  EXPECT_EQ(regions[0].type, SurfaceType::kSphere);
}

TEST(RetypeInaccurateCurvedTest, TorusWithNoValidFitLeftTakesTheProposalThatLowersEMost) {
  // plate_boss's boss top at 0.15 h: typed a torus on a ring at its rim,
  // then grown over the whole disc (radius 6) and the first 25 degrees of
  // its edge round (radius 2), where only a spindle torus with its cusp on
  // the disc fits. The proposals are the plane and the curved type of S1's
  // order; on these vertices the curved one follows the round's start and
  // lowers E more than the plane (the expansion after hands those rows to
  // the round).
  Sheet s;
  testing::BuildDiscWithRoundStart(/*distance=*/0.15, &s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions(1);
  regions[0].type = SurfaceType::kTorus;
  regions[0].surface = Torus{.center = Eigen::Vector3d(0, 0, -2),
                             .axis_direction = Eigen::Vector3d::UnitZ(),
                             .major_radius = 6.0,
                             .minor_radius = 2.0};  // the ring it was typed on
  RebuildVertexLists(labels, &regions);
  ASSERT_FALSE(FitType(s.c, SurfaceType::kTorus, regions[0].vertices).ok());
  const double before = TotalEnergy(s.c, labels, regions);
  const std::optional<Move> plane = RetypeDelta(s.c, regions[0], SurfaceType::kPlane);
  ASSERT_TRUE(plane.has_value());
  ASSERT_LT(plane->delta, 0.0);

  EXPECT_EQ(RetypeInaccurateCurved(s.c, &regions), std::vector<int>{0});
  EXPECT_NE(regions[0].type, SurfaceType::kTorus);
  EXPECT_LE(TotalEnergy(s.c, labels, regions) - before, plane->delta + 1e-6 * std::abs(before));
}

// A quarter of a cone around the z axis, 150 long, radius 6.35 at z = 0 and
// half angle `degrees` (a CAD part's edge round is 6.35 across and about
// 150 long); th_dis 0.75, th_nm 5, as that part remeshed has.
void QuarterCone(double degrees, Sheet* s) {
  const double half_angle = degrees * std::numbers::pi / 180.0;
  BuildSheet(
      [half_angle](double phi, double z) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const double radius = 6.35 + z * std::tan(half_angle);
        return std::pair{Eigen::Vector3d(radius * radial + z * Eigen::Vector3d::UnitZ()),
                         Eigen::Vector3d(std::cos(half_angle) * radial -
                                         std::sin(half_angle) * Eigen::Vector3d::UnitZ())};
      },
      0.0, std::numbers::pi / 2, 10, -75.0, 75.0, 151, /*distance=*/0.75, /*angle_deg=*/5.0, s);
}

TEST(RetypeToSimplerLimitsTest, ACylinderFittedAsAWideningConeBecomesACylinder) {
  // The round as a cone of half angle 0.06 degrees (0.16 wider at one end):
  // the cylinder misses it by 0.08 at most, well within the noise unit
  // th_dis / 3, and saves a parameter.
  Sheet s;
  QuarterCone(0.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(s, SurfaceType::kCone, &labels);
  const double half_angle = 0.06 * std::numbers::pi / 180.0;
  regions[0].surface = Cone{.apex = Eigen::Vector3d(0.0, 0.0, -6.35 / std::tan(half_angle)),
                            .axis_direction = Eigen::Vector3d::UnitZ(),
                            .half_angle = half_angle};

  EXPECT_EQ(RetypeToSimplerLimits(s.c, &regions), 1);
  ASSERT_EQ(regions[0].type, SurfaceType::kCylinder);
  EXPECT_NEAR(std::get<Cylinder>(regions[0].surface).radius, 6.35, 0.01);
}

// A quarter cone of 1-degree draft as one cone region, its cone fitted.
std::vector<RegionState> DraftedCone(Sheet* s) {
  QuarterCone(1.0, s);
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(*s, SurfaceType::kCone, &labels);
  regions[0].surface = FitType(s->c, SurfaceType::kCone, regions[0].vertices).surface;
  return regions;
}

TEST(RetypeToSimplerLimitsTest, ADraftedConeStaysACone) {
  // A 1-degree draft widens by 2.6 over the 150: the cylinder misses the
  // ends by over th_dis.
  Sheet s;
  std::vector<RegionState> regions = DraftedCone(&s);

  EXPECT_EQ(RetypeToSimplerLimits(s.c, &regions), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
}

TEST(RetypeToSimplerLimitsTest, ARefusalIsKeptForTheRegionAsItStandsOnly) {
  // The drafted cone refuses its cylinder: kept, it is not asked again
  // while it is the same; a region changed since (its surface moved) is.
  Sheet s;
  std::vector<RegionState> regions = DraftedCone(&s);
  KeptPrices kept;
  EXPECT_FALSE(kept.Refused(regions, 0, KeptPrices::kSimplerLimit));
  EXPECT_EQ(RetypeToSimplerLimits(s.c, &regions, &kept), 0);
  EXPECT_TRUE(kept.Refused(regions, 0, KeptPrices::kSimplerLimit));
  EXPECT_FALSE(kept.Refused(regions, 0, KeptPrices::kInaccurateCurved));
  EXPECT_EQ(RetypeToSimplerLimits(s.c, &regions, &kept), 0);
  std::get<Cone>(regions[0].surface).apex += Eigen::Vector3d(0.0, 0.0, 1e-9);
  EXPECT_FALSE(kept.Refused(regions, 0, KeptPrices::kSimplerLimit));
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
}

TEST(RetypeToSimplerLimitsTest, AHugeCylinderAlongAFlatSideBecomesAPlaneAndARoundStays) {
  // A flat side 60 long and 10 high grown as a cylinder of r 572 whose axis
  // runs along it; beside it, a quarter of a cylinder of radius 5.
  Sheet side;
  testing::BuildFlatSide(&side);
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(side, SurfaceType::kCylinder, &labels);
  regions[0].surface = Cylinder{.axis_origin = Eigen::Vector3d(0.0, 572.0, 0.0),
                                .axis_direction = Eigen::Vector3d::UnitX(),
                                .radius = 572.0};
  EXPECT_EQ(RetypeToSimplerLimits(side.c, &regions), 1);
  EXPECT_EQ(regions[0].type, SurfaceType::kPlane);

  Sheet round;
  QuarterCylinder(&round);
  regions = RegionsFromLabels(round.c, std::vector<int>(round.u.size(), 0),
                              {SurfaceType::kCylinder});
  EXPECT_EQ(RetypeToSimplerLimits(round.c, &regions), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
}

}  // namespace
}  // namespace meshseg::segment_internal
