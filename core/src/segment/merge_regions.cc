#include "segment/merge_regions.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "segment/energy.h"
#include "segment/region_graph.h"

namespace meshseg::segment_internal {

absl::StatusOr<int> MergeRegions(const SegmentContext& c, std::vector<int>* labels,
                                 std::vector<RegionState>* regions, KeptPrices* prices) {
  ReestimatedRegions region(c, *regions);
  KeptPrices local;
  KeptPrices& kept = prices != nullptr ? *prices : local;
  // The price of each region's drop, by id and vertex count (as the
  // re-estimations), taken from `kept` where a step before priced it on
  // the same regions.
  std::map<std::pair<int, std::size_t>, double> drops;
  auto drop = [&](int id) {
    const std::pair key{id, (*regions)[id].vertices.size()};
    auto it = drops.find(key);
    if (it == drops.end()) {
      it = drops.emplace(key, kept.Drop(c, *labels, *regions, region, id).delta).first;
    }
    return it->second;
  };
  return MergeBestPairs(
      c, labels, regions, [](const RegionArc& arc) { return arc.smooth; },
      [&](int a, int b) -> std::optional<PairMerge> {
        const std::optional<Move>& move = kept.Merge(c, *labels, *regions, region, a, b);
        if (!move || !(move->delta < 0.0)) return std::nullopt;
        // A region whose vertices lower E more by going each to the
        // neighbour that meets it best, not all to one (rows of two faces;
        // a curved fit grown over a small face and the rows around it), is
        // no piece of one surface with the other: the better move is its
        // drop, which DropRegions (drop_regions.h) makes before the pair
        // is priced again.
        if (std::min(drop(a), drop(b)) < move->delta) return std::nullopt;
        return PairMerge{.score = -move->delta, .type = move->type, .surface = move->surface};
      },
      [&](std::span<const std::pair<int, int>> pairs) {
        // The tests about to be made, priced together: the merges, then
        // the drops of the members of a merge that lowers E that are not
        // priced yet in this step (the ones the tests will ask for). Every
        // test of a round comes after this, and no region changes within a
        // round: the regions are compared with the kept ones once a round.
        kept.Touch();
        kept.PriceMerges(c, *labels, *regions, region, pairs);
        std::vector<int> members;
        for (const auto& [a, b] : pairs) {
          const std::optional<Move>& move = kept.Merge(c, *labels, *regions, region, a, b);
          if (!move || !(move->delta < 0.0)) continue;
          for (const int id : {a, b}) {
            if (!drops.contains({id, (*regions)[id].vertices.size()})) members.push_back(id);
          }
        }
        std::sort(members.begin(), members.end());
        members.erase(std::unique(members.begin(), members.end()), members.end());
        kept.PriceDrops(c, *labels, *regions, region, members);
      });
}

}  // namespace meshseg::segment_internal
