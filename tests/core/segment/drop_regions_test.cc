// DropRegions (the drop that lowers the segmentation energy most,
// drop_regions.h) and its price DropDelta (energy.h) on sheets: the priced
// change of E is the change of the total; strips that lie on their
// neighbours' surfaces are dropped whatever their type; a small face across
// a crease stays.
#include "segment/drop_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "segment/energy.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Fold45;
using testing::RegionsFromLabels;
using testing::RippledFoldWithStrip;
using testing::Sheet;

constexpr double kSigma = 0.01;

TEST(DropDeltaTest, IsTheChangeOfTheTotalEnergy) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(kSigma, &s, &labels);
  const double before = TotalEnergy(s.c, labels, regions);
  const DropMove move = DropDelta(s.c, labels, regions, 2);
  // Both sides take rows, and both are refitted to what they then hold.
  ASSERT_EQ(move.takers, (std::vector<int>{0, 1}));
  ASSERT_EQ(move.surfaces.size(), 2u);
  for (std::size_t k = 0; k < regions[2].vertices.size(); ++k) {
    labels[regions[2].vertices[k]] = move.next[k];
  }
  regions[0].surface = move.surfaces[0];
  regions[1].surface = move.surfaces[1];
  regions[2].alive = false;
  RebuildVertexLists(labels, &regions);
  const double after = TotalEnergy(s.c, labels, regions);
  EXPECT_NEAR(after - before, move.delta, 1e-9 * std::abs(before));
  EXPECT_LT(move.delta, 0.0);
}

TEST(DropRegionsTest, StripOnItsNeighboursIsDropped) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(kSigma, &s, &labels);
  EXPECT_EQ(DropRegions(s.c, &labels, &regions).value(), 1);
  EXPECT_FALSE(regions[2].alive);
  EXPECT_TRUE(regions[2].vertices.empty());
  EXPECT_TRUE(regions[0].alive);
  EXPECT_TRUE(regions[1].alive);
  // Each row goes to the face it lies on.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], s.u[v] < 5.5 ? 0 : 1) << "u " << s.u[v];
  }
}

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

// A strip of a curved band fits a plane within the noise; its vertices lie
// on the band's cone, which takes them all.
TEST(DropRegionsTest, PlaneStripOfACurvedBandIsDropped) {
  Sheet s;
  testing::BuildChamfer(kSigma, 0.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = BandWithStrip(s, SurfaceType::kPlane, &labels);
  ASSERT_EQ(regions[3].vertices.size(), 2u * testing::kChamferAround);
  const std::vector<int> before = labels;
  EXPECT_EQ(DropRegions(s.c, &labels, &regions).value(), 1);
  EXPECT_FALSE(regions[3].alive);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], before[v] == 3 ? 0 : before[v]) << "row " << s.u[v];
  }
}

// Typed as the band's own cone, the strip and the band are one surface in
// two labels: one of them goes (whichever saves more), and the band's
// middle rows and the strip end in one region.
TEST(DropRegionsTest, ConeStripOfAConeBandEndsInOneRegionWithIt) {
  Sheet s;
  testing::BuildChamfer(kSigma, 0.0, &s);
  std::vector<int> labels;
  std::vector<RegionState> regions = BandWithStrip(s, SurfaceType::kCone, &labels);
  EXPECT_EQ(DropRegions(s.c, &labels, &regions).value(), 1);
  EXPECT_NE(regions[0].alive, regions[3].alive);
  const int band = regions[0].alive ? 0 : 3;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] >= 12.0 && s.u[v] <= 17.0) {
      EXPECT_EQ(labels[v], band) << "row " << s.u[v];
    }
  }
}

// The two rows past a 45-degree fold at u = 10 (42 vertices, under the
// 200 faces of a primitive) are a face of their own: on the plane before
// the fold they would be outliers. The rows stay.
TEST(DropRegionsTest, SmallFaceAcrossACreaseStays) {
  Sheet s;
  BuildSheet(Fold45(10.0), 0.0, 12.0, 13, 0.0, 20.0, 21, /*distance=*/0.05, /*angle_deg=*/8.0,
             &s);
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.u[v] > 10.0 ? 1 : 0;
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kPlane});
  const std::vector<int> before = labels;
  EXPECT_GT(DropDelta(s.c, labels, regions, 1).delta, 0.0);
  EXPECT_EQ(DropRegions(s.c, &labels, &regions).value(), 0);
  EXPECT_TRUE(regions[1].alive);
  EXPECT_EQ(labels, before);
}

}  // namespace
}  // namespace meshseg::segment_internal
