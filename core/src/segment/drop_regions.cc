#include "segment/drop_regions.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "meshseg/status_macros.h"
#include "segment/energy.h"

namespace meshseg::segment_internal {

absl::StatusOr<int> DropRegions(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions, KeptPrices* prices) {
  KeptPrices local;
  KeptPrices& kept = prices != nullptr ? *prices : local;
  kept.Touch();
  ReestimatedRegions region(c, *regions);
  // Each region's priced drop, until a drop changes it or a region next to it.
  std::vector<std::optional<DropMove>> priced(regions->size());
  int dropped = 0;
  for (;;) {
    MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
    std::vector<int> unpriced;
    for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
      const RegionState& r = (*regions)[id];
      if (r.alive && !r.vertices.empty() && !priced[id]) unpriced.push_back(id);
    }
    kept.PriceDrops(c, *labels, *regions, region, unpriced);
    int best = -1;
    for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
      const RegionState& r = (*regions)[id];
      if (!r.alive || r.vertices.empty()) continue;
      if (!priced[id]) priced[id] = kept.Drop(c, *labels, *regions, region, id);
      if (priced[id]->delta < 0.0 && (best < 0 || priced[id]->delta < priced[best]->delta)) {
        best = id;
      }
    }
    if (best < 0) return dropped;
    const DropMove move = *std::move(priced[best]);
    RegionState& r = (*regions)[best];
    // The regions whose price this drop changes: r's neighbours (r was
    // beside them and its vertices now border them) and theirs (a taker
    // changed its vertices and surface).
    std::vector<int> stale = RegionsAround(c, *labels, *regions, best);
    for (std::size_t k = 0; k < r.vertices.size(); ++k) (*labels)[r.vertices[k]] = move.next[k];
    for (std::size_t t = 0; t < move.takers.size(); ++t) {
      RegionState& taker = (*regions)[move.takers[t]];
      for (std::size_t k = 0; k < r.vertices.size(); ++k) {
        if (move.next[k] == move.takers[t]) taker.vertices.push_back(r.vertices[k]);
      }
      std::sort(taker.vertices.begin(), taker.vertices.end());
      taker.surface = move.surfaces[t];
    }
    r.vertices.clear();
    r.alive = false;
    for (const int t : move.takers) {
      const std::vector<int> around = RegionsAround(c, *labels, *regions, t);
      stale.insert(stale.end(), around.begin(), around.end());
    }
    for (const int id : stale) priced[id].reset();
    kept.Touch();
    ++dropped;
  }
}

}  // namespace meshseg::segment_internal
