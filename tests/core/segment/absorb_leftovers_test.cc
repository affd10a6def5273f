// ReleaseNarrowPlanes on stepped_shaft's chamfer as a sheet
// (sheet_context.h): a strip of its band labelled apart; ReleaseSmallRegions
// and ReleaseNarrowPlanes on a fold: a small face of its own across the
// crease, and the same rows on a flat sheet.
#include "segment/absorb_leftovers.h"

#include <gtest/gtest.h>

#include <vector>

#include "segment/retype_by_interior.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Fold45;
using testing::RegionsFromLabels;
using testing::Sheet;

constexpr double kSigma = 0.01;

// The chamfer labelled band 0 (a cone), cylinder 1, top 2, and two rows of
// the band 3, of type `strip`, between its halves.
std::vector<RegionState> BandWithStrip(const Sheet& s, SurfaceType strip,
                                       std::vector<int>* labels) {
  labels->resize(s.u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) {
    const double row = s.u[v];
    (*labels)[v] = row == 14.0 || row == 15.0         ? 3
                   : row < testing::kChamferConeStart ? 1
                   : row > testing::kChamferConeEnd   ? 2
                                                      : 0;
  }
  return RegionsFromLabels(
      s.c, *labels, {SurfaceType::kCone, SurfaceType::kCylinder, SurfaceType::kPlane, strip});
}

TEST(ReleaseNarrowPlanesTest, PlaneStripWithoutInteriorIsReleased) {
  Sheet s;
  testing::BuildChamfer(kSigma, 0.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = BandWithStrip(s, SurfaceType::kPlane, &labels);
  ASSERT_EQ(regions[3].vertices.size(), 2u * testing::kChamferAround);
  const std::vector<int> before = labels;
  EXPECT_EQ(ReleaseNarrowPlanes(s.c, &labels, &regions), 1);
  EXPECT_FALSE(regions[3].alive);
  EXPECT_TRUE(regions[3].vertices.empty());
  // The strip's vertices are free; the top (a plane with an interior) and
  // the rest keep theirs.
  EXPECT_TRUE(regions[2].alive);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], before[v] == 3 ? -1 : before[v]) << "row " << s.u[v];
  }
}

TEST(ReleaseNarrowPlanesTest, CurvedStripStays) {
  Sheet s;
  testing::BuildChamfer(kSigma, 0.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = BandWithStrip(s, SurfaceType::kCone, &labels);
  const std::vector<int> before = labels;
  EXPECT_EQ(ReleaseNarrowPlanes(s.c, &labels, &regions), 0);
  EXPECT_TRUE(regions[3].alive);
  EXPECT_EQ(labels, before);
}

// `s` a fold at u = 10 (past it rising at 45 degrees; `crease` > 12 makes
// it flat) over u in [0, 12], v in [0, 20], with the two rows past u = 10
// (42 vertices) a plane region 1 of their own beside plane 0.
std::vector<RegionState> TwoRowsPastAFold(double crease, Sheet* s, std::vector<int>* labels) {
  BuildSheet(Fold45(crease), 0.0, 12.0, 13, 0.0, 20.0, 21, /*distance=*/0.05, /*angle_deg=*/8.0, s);
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) (*labels)[v] = s->u[v] > 10.0 ? 1 : 0;
  return RegionsFromLabels(s->c, *labels, {SurfaceType::kPlane, SurfaceType::kPlane});
}

// A plane under the size floor that lies on no neighbour's surface is a
// face of its own (test_piece's boss top at 1.5 h and noise 0: 41 vertices,
// released and absorbed by the boss cone, which became a sphere).
TEST(ReleaseSmallRegionsTest, SmallFaceAcrossACreaseStays) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = TwoRowsPastAFold(10.0, &s, &labels);
  ASSERT_LT(regions[1].vertices.size(), kMinRegionVertices);
  ASSERT_GE(regions[1].vertices.size(), kMinInteriorVertices);
  const std::vector<int> before = labels;
  EXPECT_EQ(ReleaseSmallRegions(s.c, &labels, &regions), 0);
  EXPECT_TRUE(regions[1].alive);
  EXPECT_EQ(labels, before);
}

// The same rows on the flat sheet lie on plane 0: a fragment, released.
TEST(ReleaseSmallRegionsTest, SmallPlaneOnItsNeighboursSurfaceIsReleased) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = TwoRowsPastAFold(100.0, &s, &labels);
  EXPECT_EQ(ReleaseSmallRegions(s.c, &labels, &regions), 1);
  EXPECT_FALSE(regions[1].alive);
  EXPECT_TRUE(regions[0].alive);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], s.u[v] > 10.0 ? -1 : 0) << "u " << s.u[v];
  }
}

// Past the crease the sheet bends (z = (u - 9)^2 / 2): three rows of it
// (45 vertices) typed plane miss their plane by far more than the noise.
// Such a region is a fragment on a rounded rim, not a face: released.
TEST(ReleaseSmallRegionsTest, BentSmallPlaneIsReleased) {
  Sheet s;
  const auto bend = [](double u, double v) {
    if (u <= 9.0) return std::pair{Eigen::Vector3d(u, v, 0.0), Eigen::Vector3d(0, 0, 1)};
    const double t = u - 9.0;
    return std::pair{Eigen::Vector3d(u, v, t * t / 2), Eigen::Vector3d(-t, 0, 1).normalized()};
  };
  BuildSheet(bend, 0.0, 12.0, 13, 0.0, 14.0, 15, /*distance=*/0.05, /*angle_deg=*/8.0, &s);
  s.c.noise_sigma = 0.01;
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.u[v] > 9.0 ? 1 : 0;
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kPlane});
  ASSERT_EQ(regions[1].vertices.size(), 45u);
  EXPECT_EQ(ReleaseSmallRegions(s.c, &labels, &regions), 1);
  EXPECT_FALSE(regions[1].alive);
}

// A plane too narrow for an interior that lies on no neighbour's surface is
// a face of its own (test_piece's boss top at 1.25 h: 64 vertices, under 30
// of them interior, released and absorbed by the boss cone, which it bent
// from 20.6 to 31.2 degrees). Here: the two rows past a 45-degree crease.
TEST(ReleaseNarrowPlanesTest, NarrowFaceAcrossACreaseStays) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = TwoRowsPastAFold(10.0, &s, &labels);
  const int ids[] = {1};
  ASSERT_LT(InteriorVertices(s.c, labels, ids, regions[1].vertices).size(), kMinInteriorVertices);
  const std::vector<int> before = labels;
  EXPECT_EQ(ReleaseNarrowPlanes(s.c, &labels, &regions), 0);
  EXPECT_TRUE(regions[1].alive);
  EXPECT_EQ(labels, before);
}

}  // namespace
}  // namespace meshseg::segment_internal
