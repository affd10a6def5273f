// RetypeInaccurateCurved on sheets cut from a cone and from a sphere.
#include "segment/merge_regions.h"

#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

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
        const Eigen::Vector3d p = t * (std::sin(half) * radial + std::cos(half) * Eigen::Vector3d::UnitZ());
        const Eigen::Vector3d n = std::cos(half) * radial - std::sin(half) * Eigen::Vector3d::UnitZ();
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

}  // namespace
}  // namespace meshseg::segment_internal
