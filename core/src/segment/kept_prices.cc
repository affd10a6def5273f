#include "segment/kept_prices.h"

#include <cstring>
#include <type_traits>
#include <variant>

namespace meshseg::segment_internal {
namespace {

// Whether two regions are the same: alive, type, surface (bit for bit) and
// vertices.
bool SameRegion(const RegionState& a, const RegionState& b) {
  if (a.alive != b.alive || a.type != b.type || a.surface.index() != b.surface.index() ||
      a.vertices != b.vertices) {
    return false;
  }
  return std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        return std::memcmp(&x, &std::get<T>(b.surface), sizeof(T)) == 0;
      },
      a.surface);
}

}  // namespace

int KeptPrices::Version(const std::vector<RegionState>& regions, int id) {
  if (seen_.size() < regions.size()) seen_.resize(regions.size());
  Seen& seen = seen_[id];
  if (seen.checked != generation_) {
    seen.checked = generation_;
    if (seen.version < 0 || !SameRegion(seen.region, regions[id])) {
      ++seen.version;
      seen.region = regions[id];
    }
  }
  return seen.version;
}

const DropMove& KeptPrices::Drop(const SegmentContext& c, const std::vector<int>& labels,
                                 const std::vector<RegionState>& regions,
                                 ReestimatedRegions& region, int id) {
  if (drops_.size() < regions.size()) drops_.resize(regions.size());
  Versions versions = {{id, Version(regions, id)}};
  for (const int o : RegionsAround(c, labels, regions, id)) {
    versions.emplace_back(o, Version(regions, o));
  }
  std::optional<DropEntry>& entry = drops_[id];
  if (!entry || entry->versions != versions) {
    entry = DropEntry{.move = DropDelta(c, labels, region, id), .versions = std::move(versions)};
  }
  return entry->move;
}

const std::optional<Move>& KeptPrices::Merge(const SegmentContext& c,
                                             const std::vector<int>& labels,
                                             const std::vector<RegionState>& regions,
                                             ReestimatedRegions& region, int a, int b) {
  Versions versions = {{a, Version(regions, a)}, {b, Version(regions, b)}};
  MergeEntry& entry = merges_[{a, b}];
  if (entry.versions != versions) {
    entry.move = MergeDelta(c, labels, region, a, b,
                            MergeTypes(regions[a].type, regions[b].type), /*below=*/0.0);
    entry.versions = std::move(versions);
  }
  return entry.move;
}

}  // namespace meshseg::segment_internal
