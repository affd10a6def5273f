// Prices of merges and drops (energy.h) kept from one step of the
// segmentation to the next. A drop's price (DropDelta) depends only on the
// region, the labels beside it and the regions around it (their vertices,
// types and surfaces, re-estimated from those); a merge's (MergeDelta) only
// on its two regions. The steps between two pricings change few regions, so
// a price is reused while those regions are as they were when it was made,
// bit for bit, and made again otherwise: the same prices, computed once.
// Prices are independent of one another (each reads the regions and labels
// as they stand), so those a step needs are made together, over the cores:
// each price is the same computation as alone, so the prices, and every
// decision made on them, do not depend on the number of threads.
#ifndef MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_
#define MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_

#include <map>
#include <optional>
#include <span>
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
  // Makes, in parallel, the prices of the drops of `ids` (and of the
  // merges of `pairs`, a < b) that are not kept: Drop (Merge) then gives
  // them without pricing, as long as nothing changes in between.
  void PriceDrops(const SegmentContext& c, const std::vector<int>& labels,
                  const std::vector<RegionState>& regions, ReestimatedRegions& region,
                  std::span<const int> ids);
  void PriceMerges(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions, ReestimatedRegions& region,
                   std::span<const std::pair<int, int>> pairs);
  // The retype and refit proposals (retype_regions.h, retype_by_interior.h,
  // refit_to_interior.h) whose refusals are kept.
  enum Proposal {
    kBentPlane,
    kInaccurateCurved,
    kSimplerLimit,
    kInteriorType,
    kInteriorSurface,
    kProposals
  };
  // Whether proposal `p` was asked of region `id` as it stands, bit for
  // bit, and made no move. A proposal reads only its region, so it would
  // make none again: only the regions changed since are asked.
  bool Refused(const std::vector<RegionState>& regions, int id, Proposal p);
  // Keeps that proposal `p` made no move on region `id` as it stands.
  void Refuse(const std::vector<RegionState>& regions, int id, Proposal p);
  // Region `id` re-estimated (Reestimated, energy.h): the re-estimation
  // kept of it as it stands, or made (and kept). Refused, Refuse and
  // Reestimation read and write region `id`'s entries only, so they may be
  // called for different regions at once after Reserve(regions.size()).
  RegionState Reestimation(const SegmentContext& c, const std::vector<RegionState>& regions,
                           int id);
  void Reserve(std::size_t region_count);
  // How many re-estimations a step took from an earlier one (Reestimate).
  long kept_reestimations() const { return kept_reestimations_; }
  // The regions may have changed since the last price: each is compared
  // again with what it was when next asked for. Between two calls the
  // regions and labels must not change (a price found current is not
  // checked again until the next).
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
  // Each price with the generation it was last found current in: within a
  // generation nothing changes, so it is not compared again.
  struct DropEntry {
    DropMove move;
    Versions versions;  // the region, then those around it
    long current = -1;
  };
  struct MergeEntry {
    std::optional<Move> move;
    Versions versions;
    long current = -1;
  };
  // A region's re-estimation (ReestimatedRegions) with the version of the
  // region it was made on: the same region, bit for bit, is re-estimated
  // the same, so a later step takes it instead of fitting again.
  struct KeptReestimation {
    int version = -1;
    RegionState region;
    double cost = 0.0;
  };
  int Version(const std::vector<RegionState>& regions, int id);
  // Version, compared again even within a generation (the retypes change
  // regions between the merge and drop steps' generations).
  int VersionNow(const std::vector<RegionState>& regions, int id);
  // Makes the re-estimations of regions `ids` in `region`, or gives it
  // those kept from an earlier step on the same regions; keeps them for
  // the next. Those to make are made in parallel, each in a
  // ReestimatedRegions of its own (the same computation as in `region`),
  // and then given to `region`.
  void Reestimate(const SegmentContext& c, const std::vector<RegionState>& regions,
                  ReestimatedRegions& region, std::span<const int> ids);
  // The versions a drop of `id` is priced on: the region, then `around`
  // (RegionsAround of it).
  Versions DropVersions(const std::vector<RegionState>& regions, int id,
                        std::span<const int> around);
  long generation_ = 0;
  std::vector<Seen> seen_;
  std::vector<std::optional<DropEntry>> drops_;
  std::map<std::pair<int, int>, MergeEntry> merges_;
  std::vector<std::optional<KeptReestimation>> reestimations_;
  // Per proposal, the version of each region it last made no move on.
  std::vector<int> refused_[kProposals];
  long kept_reestimations_ = 0;
};

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_KEPT_PRICES_H_
