// MergeRegions (the merge that lowers the segmentation energy most, energy.h)
// on sheets: a half cylinder in two regions, a cone band in two pieces typed
// apart, a round in two plane strips, two planes at a crease, a cylinder
// with its tangent fillet.
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
using testing::TrueAreas;

constexpr double kPi = std::numbers::pi;
constexpr double kSigma = 0.01;

int AliveCount(const std::vector<RegionState>& regions) {
  return static_cast<int>(
      std::count_if(regions.begin(), regions.end(), [](const RegionState& r) { return r.alive; }));
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
  TrueAreas(&out.s);
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
  // Seed 000's beta2 (0.9) asks one surface to fit 90 % of both regions; here
  // each region's own cylinder fits only about 6 in 7 of its vertices, and
  // the union's fits each as well.
  SplitHalfCylinder h = BuildSplitHalfCylinder(/*step=*/0.0);
  std::vector<RegionState> regions =
      RegionsFromLabels(h.s.c, h.labels, {SurfaceType::kCylinder, SurfaceType::kCylinder});
  for (const RegionState& r : regions) {
    ASSERT_LT(FitFraction(h.s.c, r.surface, r.vertices, h.s.c.tolerance), 0.9);
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


// Three quarters of a turn of a 45-degree cone band (axis z) from radius 5
// down to 3.5, 13 rows by 64 vertices around; th_dis 5 sigma, th_nm 10
// degrees; label 0 below angle `split`, 1 above.
void SplitCone(double split, Sheet* s, std::vector<int>* labels) {
  BuildSheet(
      [](double t, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        return std::pair{Eigen::Vector3d((5.0 - t) * radial + t * z),
                         Eigen::Vector3d((radial + z).normalized())};
      },
      0.0, 1.5, 13, 0.0, 1.5 * kPi, 64, /*distance=*/5.0 * kSigma, /*angle_deg=*/10.0, s);
  TrueAreas(s);
  s->c.noise_sigma = kSigma;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) (*labels)[v] = s->v[v] < split ? 0 : 1;
}

TEST(MergeRegionsTest, ConeBandTypedApartIsOneCone) {
  // One piece passes as a sphere within the tolerances on a band this
  // narrow, the other as a cone; one cone explains both with fewer
  // parameters than the two.
  Sheet s;
  std::vector<int> labels;
  SplitCone(0.75 * kPi, &s, &labels);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kSphere, SurfaceType::kCone});
  ASSERT_GT(FitType(s.c, SurfaceType::kSphere, regions[0].vertices).rms_distance, 0.25 * kSigma);

  EXPECT_EQ(MergeRegions(s.c, &labels, &regions).value(), 1);
  ASSERT_EQ(AliveCount(regions), 1);
  const int kept = regions[0].alive ? 0 : 1;
  EXPECT_EQ(regions[kept].vertices.size(), s.u.size());
  ASSERT_EQ(regions[kept].type, SurfaceType::kCone);
  EXPECT_NEAR(std::get<Cone>(regions[kept].surface).half_angle, kPi / 4.0, 1e-6);
}

// A strip of a round of radius 4 from -20 to 20 degrees (axis z, 31
// columns by 24 rows 0.25 apart) whose radius ripples by `ripple` along the
// axis with a period of 2 (a stand-in for the meshing error of a CT part),
// or, with `crease_deg` > 0, two planes meeting at that angle along its
// middle; label 0 for the first half of the columns, 1 for the rest.
void PlaneStrips(double ripple, double crease_deg, Sheet* s, std::vector<int>* labels) {
  constexpr double kRadius = 4.0;
  const double bend = crease_deg * kPi / 180.0;
  BuildSheet(
      [&](double z, double phi) {
        if (bend > 0.0) {
          const double tilt = (phi < 0.0 ? -1.0 : 1.0) * bend / 2.0;
          const Eigen::Vector3d along(-std::sin(tilt), std::cos(tilt), 0.0);
          const Eigen::Vector3d normal(std::cos(tilt), std::sin(tilt), 0.0);
          return std::pair{Eigen::Vector3d(kRadius * Eigen::Vector3d::UnitX() +
                                           kRadius * phi * along + z * Eigen::Vector3d::UnitZ()),
                           normal};
        }
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const double r = kRadius + ripple * std::sin(kPi * z);
        return std::pair{Eigen::Vector3d(r * radial + z * Eigen::Vector3d::UnitZ()), radial};
      },
      0.0, 5.75, 24, -20.0 * kPi / 180.0, 20.0 * kPi / 180.0, 31, /*distance=*/5.0 * kSigma,
      /*angle_deg=*/10.0, s);
  TrueAreas(s);
  s->c.noise_sigma = kSigma;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) (*labels)[v] = s->v[v] < 0.0 ? 0 : 1;
}

TEST(MergeRegionsTest, RoundInTwoPlaneStripsIsOneCylinder) {
  // Each half of the strip passes as a plane, its sagitta within th_dis;
  // the cylinder meets the union (ripple 1.8 sigma) far closer than either
  // plane meets its half.
  Sheet s;
  std::vector<int> labels;
  PlaneStrips(/*ripple=*/1.8 * kSigma, /*crease_deg=*/0.0, &s, &labels);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kPlane});

  EXPECT_EQ(MergeRegions(s.c, &labels, &regions).value(), 1);
  const int kept = regions[0].alive ? 0 : 1;
  ASSERT_EQ(regions[kept].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[kept].vertices.size(), s.u.size());
  EXPECT_NEAR(std::get<Cylinder>(regions[kept].surface).radius, 4.0, 0.01);
}

TEST(MergeRegionsTest, PlanesAtACreaseStayApart) {
  // Two exact planes meeting at 10 degrees (under th_bnd, so the arc is
  // smooth): a cylinder through both misses the crease by more than the
  // boundary and the second label cost are worth.
  Sheet s;
  std::vector<int> labels;
  PlaneStrips(/*ripple=*/0.0, /*crease_deg=*/10.0, &s, &labels);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kPlane});
  EXPECT_EQ(MergeRegions(s.c, &labels, &regions).value(), 0);
  EXPECT_EQ(AliveCount(regions), 2);
}

TEST(MergeRegionsTest, CylinderAndItsTangentFilletStayApart) {
  // A cylinder of radius 5 (label 0) and a quarter-round of radius 2
  // turning in from its top (label 1): the arc between them is smooth, but
  // no one surface fits both.
  Sheet s;
  constexpr int kCylinderRows = 11;
  BuildSheet(
      [](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row <= kCylinderRows - 1) {
          return std::pair{Eigen::Vector3d(5.0 * radial + 0.25 * row * z), radial};
        }
        const double t = (row - (kCylinderRows - 1)) * (kPi / 2.0) / 12.0;
        const Eigen::Vector3d n = std::cos(t) * radial + std::sin(t) * z;
        return std::pair{Eigen::Vector3d(3.0 * radial + 2.5 * z + 2.0 * n), n};
      },
      0.0, kCylinderRows + 11, kCylinderRows + 12, 0.0, 1.5 * kPi, 64, /*distance=*/5.0 * kSigma,
      /*angle_deg=*/10.0, &s);
  TrueAreas(&s);
  s.c.noise_sigma = kSigma;
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.u[v] <= kCylinderRows - 1 ? 0 : 1;
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kCylinder, SurfaceType::kTorus});
  EXPECT_EQ(MergeRegions(s.c, &labels, &regions).value(), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[1].type, SurfaceType::kTorus);
}

}  // namespace
}  // namespace meshseg::segment_internal
