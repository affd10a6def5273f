// KeptPrices (kept_prices.h) on a folded sheet with a strip along the fold
// (RippledFoldWithStrip): a kept price is the price DropDelta / MergeDelta
// give on the same regions, and is made again once a region it depends on
// changes.
#include "segment/kept_prices.h"

#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::RippledFoldWithStrip;
using testing::Sheet;

TEST(KeptPricesTest, ReusesAPriceWhileItsRegionsAreUnchangedAndRemakesItAfter) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(0.01, &s, &labels);
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
  if (pays) {
    EXPECT_EQ(merge->delta, direct->delta);
  }
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

TEST(KeptPricesTest, PricesMadeTogetherAreThePricesMadeOneByOne) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(0.01, &s, &labels);
  // Re-estimated regions: the prices made together read re-estimations
  // made before them.
  ReestimatedRegions region(s.c, regions);
  KeptPrices together;
  const std::vector<int> ids = {0, 1, 2};
  const std::vector<std::pair<int, int>> pairs = {{0, 1}, {0, 2}, {1, 2}};
  together.PriceDrops(s.c, labels, regions, region, ids);
  together.PriceMerges(s.c, labels, regions, region, pairs);
  ReestimatedRegions alone(s.c, regions);
  for (const int id : ids) {
    const DropMove& kept = together.Drop(s.c, labels, regions, region, id);
    const DropMove direct = DropDelta(s.c, labels, alone, id);
    EXPECT_EQ(kept.delta, direct.delta) << "drop of " << id;
    EXPECT_EQ(kept.next, direct.next) << "drop of " << id;
    EXPECT_EQ(kept.takers, direct.takers) << "drop of " << id;
  }
  for (const auto& [a, b] : pairs) {
    const std::optional<Move>& kept = together.Merge(s.c, labels, regions, region, a, b);
    const std::optional<Move> direct =
        MergeDelta(s.c, labels, alone, a, b, MergeTypes(regions[a].type, regions[b].type),
                   /*below=*/0.0);
    ASSERT_EQ(kept.has_value(), direct.has_value()) << "merge of " << a << ", " << b;
    if (kept) {
      EXPECT_EQ(kept->delta, direct->delta) << "merge of " << a << ", " << b;
    }
  }
}

// Whether two re-estimations are the same, bit for bit.
void ExpectSameBits(ReestimatedRegions& kept, ReestimatedRegions& fresh, int id) {
  EXPECT_EQ(kept(id).type, fresh(id).type) << "region " << id;
  EXPECT_EQ(kept(id).vertices, fresh(id).vertices) << "region " << id;
  ASSERT_EQ(kept(id).surface.index(), fresh(id).surface.index()) << "region " << id;
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        EXPECT_EQ(std::memcmp(&x, &std::get<T>(fresh(id).surface), sizeof(T)), 0)
            << "region " << id;
      },
      kept(id).surface);
  const double a = kept.Cost(id), b = fresh.Cost(id);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "region " << id << ": " << a << " vs " << b;
}

// A later step pricing the merge of `a` and `b` with `kept`: `kept_after`
// re-estimations taken from earlier steps so far, and both members'
// re-estimations are what a fresh re-estimation gives.
void ExpectLaterStep(const Sheet& s, const std::vector<int>& labels,
                     const std::vector<RegionState>& regions, KeptPrices* kept, int a, int b,
                     long kept_after) {
  kept->Touch();
  ReestimatedRegions step(s.c, regions);
  kept->PriceMerges(s.c, labels, regions, step, std::vector<std::pair<int, int>>{{a, b}});
  EXPECT_EQ(kept->kept_reestimations(), kept_after) << "merge of " << a << ", " << b;
  ReestimatedRegions fresh(s.c, regions);
  ExpectSameBits(step, fresh, a);
  ExpectSameBits(step, fresh, b);
}

TEST(KeptPricesTest, AReestimationKeptFromAnEarlierStepIsAFreshOneBitForBit) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(0.01, &s, &labels);
  KeptPrices kept;
  {
    // A first step re-estimates every region (to price their drops).
    ReestimatedRegions first(s.c, regions);
    kept.PriceDrops(s.c, labels, regions, first, std::vector<int>{0, 1, 2});
  }
  EXPECT_EQ(kept.kept_reestimations(), 0);
  // The same regions: both members' re-estimations are kept ones.
  ExpectLaterStep(s, labels, regions, &kept, 0, 2, 2);
  // Region 1 tilted: its re-estimation is made again, region 0's is kept.
  std::get<Plane>(regions[1].surface).normal =
      (std::get<Plane>(regions[1].surface).normal + Eigen::Vector3d(0.0, 0.2, 0.0)).normalized();
  ExpectLaterStep(s, labels, regions, &kept, 0, 1, 3);
}

TEST(KeptPricesTest, ARegionThatIsItsKeptReestimationIsNotReestimatedAgain) {
  // A step between two pricings (an expansion's last re-estimation) sets
  // regions 0 and 2 to their re-estimations and moves no vertex: each is
  // then its own re-estimation (the same fit to the same vertices), taken
  // as it is, and equal bit for bit to what a fresh re-estimation gives.
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = RippledFoldWithStrip(0.01, &s, &labels);
  // Regions 0 and 2 a little off their fits, so their re-estimations differ
  // from them.
  for (const int id : {0, 2}) {
    Eigen::Vector3d& normal = std::get<Plane>(regions[id].surface).normal;
    normal = (normal + Eigen::Vector3d(0.03, 0.0, 0.0)).normalized();
  }
  KeptPrices kept;
  {
    ReestimatedRegions first(s.c, regions);
    kept.PriceDrops(s.c, labels, regions, first, std::vector<int>{0, 1, 2});
  }
  for (const int id : {0, 2}) {
    const RegionState reestimated = Reestimated(s.c, regions[id]);
    // Otherwise the region's version would not change, and this tests nothing.
    ASSERT_NE(std::memcmp(&std::get<Plane>(reestimated.surface),
                          &std::get<Plane>(regions[id].surface), sizeof(Plane)),
              0)
        << "region " << id;
    regions[id] = reestimated;
  }
  ExpectLaterStep(s, labels, regions, &kept, 0, 2, 2);
  // Region 0 is its re-estimation no longer once its surface is tilted: it
  // is re-estimated again (region 2's is kept once more).
  std::get<Plane>(regions[0].surface).normal =
      (std::get<Plane>(regions[0].surface).normal + Eigen::Vector3d(0.0, 0.2, 0.0)).normalized();
  ExpectLaterStep(s, labels, regions, &kept, 0, 2, 3);
}

}  // namespace
}  // namespace meshseg::segment_internal
