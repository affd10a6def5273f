// GrowPlanesFirst and GrowInitialRegions on a sheet: a floor joined to a
// wall by a tangent fillet. (Its check against curved types is covered by
// the torus_ring draw in segment_test.cc: exact sheets give no flat seed a
// plane-like strip to grow.)
#include "segment/initial_segmentation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "segment/seeds.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Sheet;

constexpr double kStep = 0.1;    // grid spacing
constexpr double kFillet = 1.0;  // fillet radius
constexpr double kSigma = 0.01;  // the noise the context claims
constexpr double kFloor = 4.0;   // floor width before the fillet
constexpr double kWall = 2.0;    // wall height after it
// th_nm as at high noise, where the fillet's quadric reaches over the floor.
constexpr double kAngleDeg = 15.0;
// Fillet rows within th_nm of the floor or the wall: 15 degrees of turn.
constexpr double kTakenRows = 3.0;

// Arc length s along the profile: the floor z = 0 for s <= 0, a concave
// quarter-round of radius kFillet, then the wall x = kFillet; y = v.
std::pair<Eigen::Vector3d, Eigen::Vector3d> FloorFilletWall(double s, double v) {
  const double arc = kFillet * std::numbers::pi / 2.0;
  if (s <= 0.0) return {Eigen::Vector3d(s, v, 0.0), Eigen::Vector3d::UnitZ()};
  if (s <= arc) {
    const double t = s / kFillet;
    return {Eigen::Vector3d(kFillet * std::sin(t), v, kFillet * (1.0 - std::cos(t))),
            Eigen::Vector3d(-std::sin(t), 0.0, std::cos(t))};
  }
  return {Eigen::Vector3d(kFillet, v, kFillet + s - arc), -Eigen::Vector3d::UnitX()};
}

// The sheet, with curvature fields that put the fillet's seeds first in
// seed 000's order: kappa_max is exactly 1 / kFillet there (deviation 0)
// and alternates around 0 on the floor and the wall.
void BuildFloorFilletWall(Sheet* s) {
  const double arc = kFillet * std::numbers::pi / 2.0;
  const int rows = static_cast<int>(std::lround((kFloor + arc + kWall) / kStep)) + 1;
  BuildSheet(FloorFilletWall, -kFloor, arc + kWall, rows, 0.0, 3.0, 31, /*distance=*/0.05,
             /*angle_deg=*/kAngleDeg, s);
  s->c.noise_sigma = kSigma;
  const std::size_t n = s->u.size();
  s->field.mean_edge_length.assign(n, kStep);
  s->field.kappa_max.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const bool fillet = s->u[v] > 0.0 && s->u[v] <= arc;
    s->field.kappa_max[v] = fillet ? 1.0 / kFillet : (v % 2 == 0 ? 0.05 : -0.05);
  }
}

TEST(GrowPlanesFirstTest, FloorAndWallAreGrownBeforeTheFillet) {
  Sheet s;
  BuildFloorFilletWall(&s);
  std::vector<int> labels(s.u.size(), -1);
  std::vector<RegionState> regions;
  ASSERT_TRUE(GrowPlanesFirst(s.c, SeedOrder(s.c), &labels, &regions).ok());
  ASSERT_EQ(regions.size(), 2u);
  const double arc = kFillet * std::numbers::pi / 2.0;
  // Each plane holds its whole face, and at most the fillet rows within
  // th_nm of it.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const double u = s.u[v];
    if (u <= 0.0) {
      EXPECT_EQ(labels[v], labels[0]) << "floor row " << u;
    } else if (u > arc) {
      EXPECT_EQ(labels[v], labels.back()) << "wall row " << u;
    } else if (u > kTakenRows * kStep && u < arc - kTakenRows * kStep) {
      EXPECT_EQ(labels[v], -1) << "fillet row " << u;
    }
  }
  EXPECT_NE(labels[0], labels.back());
  for (const RegionState& r : regions) EXPECT_EQ(r.type, SurfaceType::kPlane);
}

TEST(GrowInitialRegionsTest, FilletIsACylinderBetweenItsPlanes) {
  Sheet s;
  BuildFloorFilletWall(&s);
  std::vector<int> labels(s.u.size(), -1);
  std::vector<RegionState> regions;
  ASSERT_TRUE(GrowInitialRegions(s.c, &labels, &regions).ok());
  const double arc = kFillet * std::numbers::pi / 2.0;
  int fillet_label = -1;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (std::abs(s.u[v] - arc / 2.0) < kStep / 2.0) fillet_label = labels[v];
  }
  ASSERT_GE(fillet_label, 0);
  EXPECT_EQ(regions[fillet_label].type, SurfaceType::kCylinder);
  int floor_in_fillet = 0;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] < -kStep / 2.0 && labels[v] == fillet_label) ++floor_in_fillet;
    if (s.u[v] <= 0.0) {
      EXPECT_EQ(regions[labels[v]].type, SurfaceType::kPlane) << "floor row " << s.u[v];
    }
  }
  // Seed 000's order alone (noise_sigma 0 skips GrowPlanesFirst) puts 62
  // floor vertices, two rows, into the fillet's region.
  EXPECT_EQ(floor_in_fillet, 0);
}

}  // namespace
}  // namespace meshseg::segment_internal
