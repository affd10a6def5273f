// RetypeInaccurateCurved on sheets cut from a cone and from a sphere;
// MergeRegions on a half cylinder in two regions.
#include "segment/merge_regions.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
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

// Half a turn of a cylinder around the x axis, x from 0 to 10, whose
// radius is 7 up to x = 5 and 7 + `step` beyond; every 7th vertex has its
// n_i and n'_i turned 20 degrees about the axis (th_nm is 5), as the crease
// rows and the noise in n'_i leave about one vertex in seven at 0.15 h.
// Labels: 0 up to x = 5, 1 beyond.
struct SplitHalfCylinder {
  Sheet s;
  std::vector<int> labels;
};

SplitHalfCylinder BuildSplitHalfCylinder(double step) {
  SplitHalfCylinder out;
  BuildSheet(
      [step](double x, double phi) {
        const Eigen::Vector3d n(0.0, std::cos(phi), std::sin(phi));
        const double radius = x <= 5.0 ? 7.0 : 7.0 + step;
        return std::pair{Eigen::Vector3d(Eigen::Vector3d(x, 0.0, 0.0) + radius * n), n};
      },
      0.0, 10.0, 41, 0.0, std::numbers::pi, 41, /*distance=*/0.15, /*angle_deg=*/5.0, &out.s);
  const Eigen::AngleAxisd turn(20.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitX());
  for (std::size_t v = 0; v < out.s.u.size(); v += 7) {
    out.s.field.normal[v] = turn * out.s.field.normal[v];
    out.s.field.smooth_normal[v] = turn * out.s.field.smooth_normal[v];
  }
  out.labels.resize(out.s.u.size());
  for (std::size_t v = 0; v < out.labels.size(); ++v) out.labels[v] = out.s.u[v] <= 5.0 ? 0 : 1;
  return out;
}

TEST(MergeRegionsTest, PiecesOfOneCylinderMergeThoughTheirOwnFitsMissBeta2) {
  // Seed 000's beta2 asks one surface to fit 90 % of both regions; here
  // each region's own cylinder fits only about 6 in 7 of its vertices, and
  // the union's fits each as well.
  SplitHalfCylinder h = BuildSplitHalfCylinder(/*step=*/0.0);
  std::vector<RegionState> regions =
      RegionsFromLabels(h.s.c, h.labels, {SurfaceType::kCylinder, SurfaceType::kCylinder});
  for (const RegionState& r : regions) {
    ASSERT_LT(FitFraction(h.s.c, r.surface, r.vertices, h.s.c.tolerance), kBeta2);
  }
  ASSERT_TRUE(MergeRegions(h.s.c, &h.labels, &regions).ok());
  EXPECT_EQ(std::count_if(regions.begin(), regions.end(),
                          [](const RegionState& r) { return r.alive; }),
            1);
  for (const RegionState& r : regions) {
    if (!r.alive) continue;
    EXPECT_EQ(r.vertices.size(), h.labels.size());
    ASSERT_EQ(r.type, SurfaceType::kCylinder);
    EXPECT_NEAR(std::get<Cylinder>(r.surface).radius, 7.0, 1e-6);
  }
}

TEST(MergeRegionsTest, CylindersOfDifferentRadiiStayApart) {
  // The same sheet with the second half 0.5 wider (over th_dis): one
  // cylinder misses half of each region, its own fits 6 in 7.
  SplitHalfCylinder h = BuildSplitHalfCylinder(/*step=*/0.5);
  std::vector<RegionState> regions =
      RegionsFromLabels(h.s.c, h.labels, {SurfaceType::kCylinder, SurfaceType::kCylinder});
  const std::vector<int> before = h.labels;
  ASSERT_TRUE(MergeRegions(h.s.c, &h.labels, &regions).ok());
  EXPECT_TRUE(regions[0].alive);
  EXPECT_TRUE(regions[1].alive);
  EXPECT_EQ(h.labels, before);
}

}  // namespace
}  // namespace meshseg::segment_internal
