// FinalizeRegions: the reported surface is fitted to the region's own
// surface, not to vertices of a small face absorbed with it; a curved
// type flat over the region without them is a plane, and a type with no
// valid fit there gives way to the one that fits.
#include "segment/finalize_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "segment/decide_type.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Fold45;
using testing::Sheet;

TEST(FinalizeRegionsTest, SurfaceFitsTheRegionNotAnAbsorbedFlap) {
  // A plane z = 0 over u < 7 and a flap bent up at 45 degrees over u > 7
  // (an eighth of the vertices), all in one plane region, as leftover
  // absorption can leave a small face. th_dis 0.3: a noisy part's 3 sigma
  // against a flap 1 high.
  Sheet s;
  BuildSheet(Fold45(7.0), 0.0, 8.0, 41, 0.0, 8.0, 41, /*distance=*/0.3, /*angle_deg=*/5.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(s, SurfaceType::kPlane, &labels);
  const Plane all = std::get<Plane>(FitType(s.c, SurfaceType::kPlane, regions[0].vertices).surface);
  ASSERT_LT(std::abs(all.normal.z()), std::cos(1.0 * std::numbers::pi / 180.0))
      << "the flap must tilt a fit to all vertices by more than 1 degree";

  const Segmentation seg = FinalizeRegions(s.c, s.mesh, labels, regions);
  ASSERT_EQ(seg.regions.size(), 1u);
  const Plane& plane = std::get<Plane>(seg.regions[0].surface);
  EXPECT_GT(std::abs(plane.normal.z()), std::cos(0.01 * std::numbers::pi / 180.0));
  EXPECT_NEAR(plane.normal.dot(plane.point), 0.0, 1e-6);  // through the origin
  // The errors still cover the flap: its far edge is 1 off the plane.
  EXPECT_NEAR(seg.regions[0].max_distance, 1.0, 1e-6);
}

TEST(FinalizeRegionsTest, CurvedRegionFlatWithoutItsFlapIsAPlane) {
  // A narrower flap (u > 7.1) and noise of 0.02 along the normals (mt19937
  // draw 1) in a region typed sphere: fitted to all of it, the sphere
  // bends toward the flap; refitted to the vertices that meet it, it is
  // flat over the region (test_piece's boss top at 0.15 h, seed 137).
  Sheet s;
  BuildSheet(Fold45(7.1), 0.0, 8.0, 41, 0.0, 8.0, 41, /*distance=*/0.3, /*angle_deg=*/5.0, &s);
  std::mt19937 random(1);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (std::size_t v = 0; v < s.u.size(); ++v) {
    s.c.graph.positions[v] += noise(random) * s.field.normal[v];
  }
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(s, SurfaceType::kSphere, &labels);
  const FitResult all = FitType(s.c, SurfaceType::kSphere, regions[0].vertices);
  ASSERT_TRUE(all.ok());
  ASSERT_FALSE(NearlyFlat(s.c, all.surface, all.rms_distance, regions[0].vertices, s.c.tolerance));
  regions[0].surface = all.surface;

  const Segmentation seg = FinalizeRegions(s.c, s.mesh, labels, regions);
  ASSERT_EQ(seg.regions.size(), 1u);
  ASSERT_EQ(seg.regions[0].type, SurfaceType::kPlane);
  const Plane& plane = std::get<Plane>(seg.regions[0].surface);
  EXPECT_GT(std::abs(plane.normal.z()), std::cos(0.05 * std::numbers::pi / 180.0));
}

TEST(FinalizeRegionsTest, RegionItsTypeCannotFitTakesTheTypeThatDoes) {
  // A flat sheet (the fold beyond its edge) in a region typed torus, with
  // the surface of a torus grown elsewhere: no torus fit to the sheet is
  // valid, and that old surface must not be reported (test_piece's boss
  // top at 0.15 h, seed 171).
  Sheet s;
  BuildSheet(Fold45(9.0), 0.0, 8.0, 41, 0.0, 8.0, 41, /*distance=*/0.3, /*angle_deg=*/5.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = testing::OneRegion(s, SurfaceType::kTorus, &labels);
  regions[0].surface = Torus{.center = Eigen::Vector3d(4.0, 4.0, -3.0),
                             .axis_direction = Eigen::Vector3d::UnitZ(),
                             .major_radius = 8.0,
                             .minor_radius = 3.0};
  ASSERT_FALSE(FitType(s.c, SurfaceType::kTorus, regions[0].vertices).ok());

  const Segmentation seg = FinalizeRegions(s.c, s.mesh, labels, regions);
  ASSERT_EQ(seg.regions.size(), 1u);
  EXPECT_EQ(seg.regions[0].type, SurfaceType::kPlane) << SurfaceTypeName(seg.regions[0].type);
  EXPECT_LT(seg.regions[0].max_distance, 1e-6);
}

}  // namespace
}  // namespace meshseg::segment_internal
