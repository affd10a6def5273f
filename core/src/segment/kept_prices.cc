#include "segment/kept_prices.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <variant>

#include <tbb/parallel_for.h>

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

int KeptPrices::VersionNow(const std::vector<RegionState>& regions, int id) {
  seen_[id].checked = -1;
  return Version(regions, id);
}

void KeptPrices::Reserve(std::size_t region_count) {
  if (seen_.size() < region_count) seen_.resize(region_count);
  if (reestimations_.size() < region_count) reestimations_.resize(region_count);
  for (std::vector<int>& refused : refused_) {
    if (refused.size() < region_count) refused.resize(region_count, -1);
  }
}

bool KeptPrices::Refused(const std::vector<RegionState>& regions, int id, Proposal p) {
  Reserve(regions.size());
  return refused_[p][id] >= 0 && refused_[p][id] == VersionNow(regions, id);
}

void KeptPrices::Refuse(const std::vector<RegionState>& regions, int id, Proposal p) {
  Reserve(regions.size());
  refused_[p][id] = VersionNow(regions, id);
}

RegionState KeptPrices::Reestimation(const SegmentContext& c,
                                     const std::vector<RegionState>& regions, int id) {
  Reserve(regions.size());
  const int version = VersionNow(regions, id);
  std::optional<KeptReestimation>& kept = reestimations_[id];
  if (!kept || kept->version != version) {
    // As Reestimate makes it (ReestimatedRegions' own computation).
    ReestimatedRegions alone(c, regions);
    kept = KeptReestimation{.version = version, .region = alone(id), .cost = alone.Cost(id)};
  }
  return kept->region;
}

void KeptPrices::Reestimate(const SegmentContext& c, const std::vector<RegionState>& regions,
                            ReestimatedRegions& region, std::span<const int> ids) {
  // Only re-estimations are kept (regions as given need no fit).
  if (!region.reestimates()) return;
  if (reestimations_.size() < regions.size()) reestimations_.resize(regions.size());
  std::vector<int> todo;
  std::vector<int> versions;
  for (const int id : ids) {
    const int version = Version(regions, id);
    std::optional<KeptReestimation>& kept = reestimations_[id];
    // A region that is, bit for bit, the re-estimation kept of an earlier
    // version (a step between re-estimated it the same way and moved none
    // of its vertices: an expansion's last re-estimation) is its own
    // re-estimation: the same fit to the same vertices does not cost less
    // than itself (PriceFit's cost is DataCost's sum, term for term), so it
    // keeps its surface, at the kept cost.
    if (kept && kept->version != version && SameRegion(kept->region, regions[id])) {
      kept->version = version;
    }
    if (kept && kept->version == version) {
      if (!region.Has(id)) {
        region.Keep(id, kept->region, kept->cost);
        ++kept_reestimations_;
      }
      continue;
    }
    if (region.Has(id)) {
      kept = KeptReestimation{.version = version, .region = region(id), .cost = region.Cost(id)};
      continue;
    }
    if (std::find(todo.begin(), todo.end(), id) != todo.end()) continue;
    todo.push_back(id);
    versions.push_back(version);
  }
  // Each re-estimation reads only its region: made on the cores, each as
  // `region` would make it.
  std::vector<KeptReestimation> made(todo.size());
  tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t k) {
    ReestimatedRegions alone(c, regions);
    made[k] = {.version = versions[k], .region = alone(todo[k]), .cost = alone.Cost(todo[k])};
  });
  for (std::size_t k = 0; k < todo.size(); ++k) {
    region.Keep(todo[k], made[k].region, made[k].cost);
    reestimations_[todo[k]] = std::move(made[k]);
  }
}

KeptPrices::Versions KeptPrices::DropVersions(const std::vector<RegionState>& regions, int id,
                                              std::span<const int> around) {
  Versions versions = {{id, Version(regions, id)}};
  for (const int o : around) versions.emplace_back(o, Version(regions, o));
  return versions;
}

void KeptPrices::PriceDrops(const SegmentContext& c, const std::vector<int>& labels,
                            const std::vector<RegionState>& regions, ReestimatedRegions& region,
                            std::span<const int> ids) {
  if (drops_.size() < regions.size()) drops_.resize(regions.size());
  // The regions around each drop read only the labels: gathered side by
  // side (each list sorted, so the same), the versions then taken in order.
  std::vector<std::vector<int>> around(ids.size());
  tbb::parallel_for(std::size_t{0}, ids.size(), [&](std::size_t k) {
    const std::optional<DropEntry>& entry = drops_[ids[k]];
    if (!entry || entry->current != generation_) {
      around[k] = RegionsAround(c, labels, regions, ids[k]);
    }
  });
  std::vector<int> todo;
  std::vector<Versions> todo_versions;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const int id = ids[k];
    std::optional<DropEntry>& entry = drops_[id];
    if (entry && entry->current == generation_) continue;
    Versions versions = DropVersions(regions, id, around[k]);
    if (entry && entry->versions == versions) {
      entry->current = generation_;
      continue;
    }
    todo.push_back(id);
    todo_versions.push_back(std::move(versions));
  }
  // A drop's price reads the re-estimations of the region and of those
  // around it (its versions); they are made first, so that the prices only
  // read `region`.
  std::vector<int> reestimate;
  for (const Versions& versions : todo_versions) {
    for (const auto& [o, version] : versions) reestimate.push_back(o);
  }
  Reestimate(c, regions, region, reestimate);
  std::vector<DropMove> moves(todo.size());
  tbb::parallel_for(std::size_t{0}, todo.size(),
                    [&](std::size_t k) { moves[k] = DropDelta(c, labels, region, todo[k]); });
  for (std::size_t k = 0; k < todo.size(); ++k) {
    drops_[todo[k]] = DropEntry{.move = std::move(moves[k]),
                                .versions = std::move(todo_versions[k]),
                                .current = generation_};
  }
}

void KeptPrices::PriceMerges(const SegmentContext& c, const std::vector<int>& labels,
                             const std::vector<RegionState>& regions, ReestimatedRegions& region,
                             std::span<const std::pair<int, int>> pairs) {
  std::vector<std::pair<int, int>> todo;
  std::vector<Versions> todo_versions;
  for (const auto& [a, b] : pairs) {
    const auto it = merges_.find({a, b});
    if (it != merges_.end() && it->second.current == generation_) continue;
    Versions versions = {{a, Version(regions, a)}, {b, Version(regions, b)}};
    if (it != merges_.end() && it->second.versions == versions) {
      it->second.current = generation_;
      continue;
    }
    todo.emplace_back(a, b);
    todo_versions.push_back(std::move(versions));
  }
  std::vector<int> reestimate;
  for (const auto& [a, b] : todo) reestimate.insert(reestimate.end(), {a, b});
  Reestimate(c, regions, region, reestimate);
  std::vector<std::optional<Move>> moves(todo.size());
  tbb::parallel_for(std::size_t{0}, todo.size(), [&](std::size_t k) {
    const auto [a, b] = todo[k];
    moves[k] = MergeDelta(c, labels, region, a, b, MergeTypes(regions[a].type, regions[b].type),
                          /*below=*/0.0);
  });
  for (std::size_t k = 0; k < todo.size(); ++k) {
    merges_[todo[k]] = MergeEntry{.move = std::move(moves[k]),
                                  .versions = std::move(todo_versions[k]),
                                  .current = generation_};
  }
}

const DropMove& KeptPrices::Drop(const SegmentContext& c, const std::vector<int>& labels,
                                 const std::vector<RegionState>& regions,
                                 ReestimatedRegions& region, int id) {
  PriceDrops(c, labels, regions, region, std::span<const int>(&id, 1));
  return drops_[id]->move;
}

const std::optional<Move>& KeptPrices::Merge(const SegmentContext& c,
                                             const std::vector<int>& labels,
                                             const std::vector<RegionState>& regions,
                                             ReestimatedRegions& region, int a, int b) {
  const std::pair<int, int> pair{a, b};
  PriceMerges(c, labels, regions, region, std::span<const std::pair<int, int>>(&pair, 1));
  return merges_.at(pair).move;
}

}  // namespace meshseg::segment_internal
