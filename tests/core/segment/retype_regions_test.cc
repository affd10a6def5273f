// RetypeInaccurateCurved on sheets cut from a cone and from a sphere.
#include "segment/retype_regions.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

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

TEST(RetypeInaccurateCurvedTest, TorusWithNoValidFitLeftBecomesAPlane) {
  // plate_boss's boss top at 0.15 h: typed a torus on a ring at its rim,
  // then grown over the whole disc (radius 6) and the first 25 degrees of
  // its edge round (radius 2), where only a spindle torus with its cusp on
  // the disc fits. A plane fits the disc, under alpha of the vertices but
  // over kStaleTypeFraction.
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

  EXPECT_EQ(RetypeInaccurateCurved(s.c, &regions), std::vector<int>{0});
  ASSERT_EQ(regions[0].type, SurfaceType::kPlane);
  EXPECT_GT(std::abs(std::get<Plane>(regions[0].surface).normal.z()),
            std::cos(1.0 * std::numbers::pi / 180.0));
}

}  // namespace
}  // namespace meshseg::segment_internal
