// Prices of merges and drops (energy.h) kept from one step of the
// segmentation to the next. A drop's price (DropDelta) depends only on the
// region, the labels beside it and the regions around it (their vertices,
// types and surfaces, re-estimated from those); a merge's (MergeDelta) only
// on its two regions. The steps between two pricings change few regions, so
// a price is reused while those regions are as they were when it was made,
// bit for bit, and made again otherwise: the same prices, computed once.
#ifndef MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_
#define MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "segment/energy.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

class KeptPrices {
 public:
  // DropDelta of region `id` with `region` (the re-estimated `regions`).
  const DropMove& Drop(const SegmentContext& c, const std::vector<int>& labels,
                       const std::vector<RegionState>& regions, ReestimatedRegions& region,
                       int id);
  // MergeDelta of regions `a` and `b` as `region` gives them, over
  // MergeTypes of their types, for a merge that lowers E (below 0).
  const std::optional<Move>& Merge(const SegmentContext& c, const std::vector<int>& labels,
                                   const std::vector<RegionState>& regions,
                                   ReestimatedRegions& region, int a, int b);
  // The regions may have changed since the last price: each is compared
  // again with what it was when next asked for.
  void Touch() { ++generation_; }

 private:
  // A region as last seen, and how many times it was seen changed.
  struct Seen {
    int version = -1;
    long checked = -1;  // the generation it was last compared in
    RegionState region;
  };
  // (id, version) of the regions a price was made on.
  using Versions = std::vector<std::pair<int, int>>;
  struct DropEntry {
    DropMove move;
    Versions versions;  // the region, then those around it
  };
  struct MergeEntry {
    std::optional<Move> move;
    Versions versions;
  };
  int Version(const std::vector<RegionState>& regions, int id);
  long generation_ = 0;
  std::vector<Seen> seen_;
  std::vector<std::optional<DropEntry>> drops_;
  std::map<std::pair<int, int>, MergeEntry> merges_;
};

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_
