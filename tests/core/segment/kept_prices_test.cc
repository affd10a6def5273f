// KeptPrices (kept_prices.h) on a folded sheet with a strip along the fold:
// a kept price is the price DropDelta / MergeDelta give on the same
// regions, and is made again once a region it depends on changes.
#include "segment/kept_prices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Fold45;
using testing::RegionsFromLabels;
using testing::Sheet;

// The sheet over u in [0, 12], v in [0, 20] folded by 45 degrees at
// u = 5.5, with a ripple of amplitude 0.01 along z; labelled 0 for u < 5,
// 1 for u > 6, and 2 for the rows u = 5 and 6 either side of the fold.
std::vector<RegionState> FoldWithStrip(Sheet* s, std::vector<int>* labels) {
  BuildSheet(
      [](double u, double v) {
        auto [p, n] = Fold45(5.5)(u, v);
        p.z() += 0.01 * std::sin(1.3 * u + 0.7 * v);
        return std::pair{p, n};
      },
      0.0, 12.0, 13, 0.0, 20.0, 21, /*distance=*/0.05, /*angle_deg=*/8.0, s);
  s->c.noise_sigma = 0.01;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) {
    (*labels)[v] = s->u[v] < 5.0 ? 0 : s->u[v] <= 6.0 ? 2 : 1;
  }
  return RegionsFromLabels(s->c, *labels,
                           {SurfaceType::kPlane, SurfaceType::kPlane, SurfaceType::kPlane});
}

TEST(KeptPricesTest, ReusesAPriceWhileItsRegionsAreUnchangedAndRemakesItAfter) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = FoldWithStrip(&s, &labels);
  KeptPrices kept;
  // The regions as given (not re-estimated), so that a changed surface
  // stays changed.
  ReestimatedRegions region(s.c, regions, /*reestimate=*/false);
  const double drop = kept.Drop(s.c, labels, regions, region, 2).delta;
  EXPECT_EQ(drop, DropDelta(s.c, labels, region, 2).delta);
  // A merge is priced for whether it lowers E: the same answer, and the
  // same price where it does.
  const std::optional<Move> merge = kept.Merge(s.c, labels, regions, region, 0, 2);
  const std::optional<Move> direct = MergeDelta(s.c, labels, region(0), 0, region(2), 2,
                                                MergeTypes(SurfaceType::kPlane,
                                                           SurfaceType::kPlane));
  ASSERT_TRUE(direct.has_value());
  const bool pays = direct->delta < 0.0;
  EXPECT_EQ(merge.has_value() && merge->delta < 0.0, pays);
  if (pays) EXPECT_EQ(merge->delta, direct->delta);
  // A later step with the same regions gets the same prices.
  kept.Touch();
  ReestimatedRegions again(s.c, regions, /*reestimate=*/false);
  EXPECT_EQ(kept.Drop(s.c, labels, regions, again, 2).delta, drop);
  // Region 1, a neighbour of the strip, tilted: the strip's drop, which
  // gives it rows, is priced again.
  std::get<Plane>(regions[1].surface).normal =
      (std::get<Plane>(regions[1].surface).normal + Eigen::Vector3d(0.0, 0.2, 0.0)).normalized();
  kept.Touch();
  ReestimatedRegions tilted(s.c, regions, /*reestimate=*/false);
  const double redone = kept.Drop(s.c, labels, regions, tilted, 2).delta;
  EXPECT_EQ(redone, DropDelta(s.c, labels, tilted, 2).delta);
  EXPECT_NE(redone, drop);
}

}  // namespace
}  // namespace meshseg::segment_internal
