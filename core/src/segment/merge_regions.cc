#include "segment/merge_regions.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "segment/energy.h"
#include "segment/region_graph.h"

namespace meshseg::segment_internal {
namespace {

// Region `r` re-estimated (PEARL's step between expansions): refitted with
// its own type if that costs less than its current surface. A region keeps
// its surface from before absorption and refinement changed its vertices;
// priced with that stale surface, any merge that refits it looks a gain.
RegionState Reestimated(const SegmentContext& c, const RegionState& r) {
  RegionState out = r;
  const std::optional<Surface> fit = FitForEnergy(c, r.type, r.vertices);
  if (fit && DataCost(c, *fit, r.vertices) < DataCost(c, r.surface, r.vertices)) {
    out.surface = *fit;
  }
  return out;
}

}  // namespace

absl::StatusOr<int> MergeRegions(const SegmentContext& c, std::vector<int>* labels,
                                 std::vector<RegionState>* regions) {
  // Re-estimated regions by id and vertex count: within this step regions
  // change only by merging, which grows them.
  std::map<std::pair<int, std::size_t>, RegionState> reestimated;
  auto region = [&](int id) -> const RegionState& {
    const RegionState& r = (*regions)[id];
    auto it = reestimated.find({id, r.vertices.size()});
    if (it == reestimated.end()) {
      it = reestimated.emplace(std::pair{id, r.vertices.size()}, Reestimated(c, r)).first;
    }
    return it->second;
  };
  return MergeBestPairs(
      c, labels, regions, [](const RegionArc& arc) { return arc.smooth; },
      [&](int a, int b) -> std::optional<PairMerge> {
        const RegionState& x = (*regions)[a];
        const RegionState& y = (*regions)[b];
        const std::optional<Move> move =
            MergeDelta(c, *labels, region(a), a, region(b), b, MergeTypes(x.type, y.type));
        if (!move || !(move->delta < 0.0)) return std::nullopt;
        // A fragment whose vertices lower E more by going each to the
        // neighbour that meets it best, not all to one (rows of two faces),
        // is no piece of one surface with either: the better move is not
        // this merge.
        const bool a_smaller = x.vertices.size() <= y.vertices.size();
        std::vector<int> takers;
        const double drop = DropDelta(c, *labels, *regions, a_smaller ? a : b, &takers);
        const std::vector<int> partner = {a_smaller ? b : a};
        if (drop < move->delta &&
            std::find(takers.begin(), takers.end(), partner[0]) == takers.end()) {
          return std::nullopt;
        }
        return PairMerge{.score = -move->delta, .type = move->type, .surface = move->surface};
      });
}

}  // namespace meshseg::segment_internal
