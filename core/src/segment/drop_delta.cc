// DropDelta (energy.h): the price of dropping one region, with the labels
// its vertices take and its takers refitted.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "segment/energy.h"

namespace meshseg::segment_internal {
namespace {

// The labels the vertices of region `id` take when it is dropped, in the
// order of its vertex list (DropDelta). Labels grow into the region from
// its border, layer by layer (each layer decided on the labels before it,
// so the result does not depend on the vertex order): a vertex takes a
// label one of its mesh neighbours already has, so no label lands apart
// from its region (an island would pay boundary edges all round).
struct DropLabeling {
  std::vector<int> next;
  double boundary_delta = 0.0;  // the change of the smoothness term
};

DropLabeling DropLabels(const SegmentContext& c, const std::vector<int>& labels,
                        ReestimatedRegions& region, int id) {
  const RegionState& r = region(id);
  const std::size_t n = r.vertices.size();
  // The index in r of each of its vertices, by vertex (-1 elsewhere): one
  // array per thread (drops are priced in parallel, kept_prices.h), set for
  // r's vertices and cleared after; a search of r's sorted list for every
  // neighbour cost more than the rest of the labeling on large regions.
  thread_local std::vector<int> index_in_r;
  if (index_in_r.size() < static_cast<std::size_t>(c.vertex_count())) {
    index_in_r.assign(c.vertex_count(), -1);
  }
  for (std::size_t k = 0; k < n; ++k) index_in_r[r.vertices[k]] = static_cast<int>(k);
  // The mesh neighbours of each vertex k of r (CSR from first[k]): the
  // index in r of a neighbour in r, or -2 - its label outside (-1 none).
  std::vector<std::size_t> first(n + 1, 0);
  std::vector<long> beside;
  beside.reserve(7 * n);  // a little above the mean degree, 6
  for (std::size_t k = 0; k < n; ++k) {
    for (const int u : c.graph.Neighbors(r.vertices[k])) {
      beside.push_back(labels[u] == id ? long{index_in_r[u]} : -2L - labels[u]);
    }
    first[k + 1] = beside.size();
  }
  for (const int v : r.vertices) index_in_r[v] = -1;
  std::vector<int> next(n, -1);
  auto label_at = [&](long b) { return b >= 0 ? next[b] : static_cast<int>(-2L - b); };
  // The labels placed next to vertex k, sorted, with repeats, into `seen`.
  std::vector<int> seen;
  auto placed_beside = [&](std::size_t k) {
    seen.clear();
    for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
      const int l = label_at(beside[e]);
      if (l >= 0) seen.push_back(l);
    }
    std::sort(seen.begin(), seen.end());
  };
  // Grows with `choose(k, seen)` (-1: not now) from every unplaced vertex
  // beside a placed one until no layer places any.
  auto grow = [&](const auto& choose) {
    std::vector<std::size_t> layer;
    for (std::size_t k = 0; k < n; ++k) {
      if (next[k] >= 0) continue;
      for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
        if (label_at(beside[e]) >= 0) {
          layer.push_back(k);
          break;
        }
      }
    }
    std::vector<uint8_t> queued(n, 0);
    std::vector<std::pair<std::size_t, int>> placed;
    while (!layer.empty()) {
      placed.clear();
      for (const std::size_t k : layer) {
        placed_beside(k);
        if (seen.empty()) continue;
        const int l = choose(k, seen);
        if (l >= 0) placed.emplace_back(k, l);
      }
      layer.clear();
      for (const auto& [k, l] : placed) next[k] = l;
      for (const auto& [k, l] : placed) {
        for (std::size_t e = first[k]; e < first[k + 1]; ++e) {
          const long j = beside[e];
          if (j >= 0 && next[j] < 0 && !queued[j]) queued[j] = 1, layer.push_back(j);
        }
      }
      for (const std::size_t k : layer) queued[k] = 0;
      std::sort(layer.begin(), layer.end());
    }
  };
  // First each vertex within th_dis of a surface beside it takes the one it
  // costs least on (ties to the lowest id).
  std::vector<std::pair<int, SurfaceDistance>> surfaces;  // made once each
  auto cost_on = [&](int l, int v) {
    for (const auto& [label, distance_to] : surfaces) {
      if (label == l) return VertexCost(c, v, distance_to);
    }
    surfaces.emplace_back(l, SurfaceDistance(region(l).surface));
    return VertexCost(c, v, surfaces.back().second);
  };
  grow([&](std::size_t k, const std::vector<int>& seen) {
    const int v = r.vertices[k];
    double best = OutlierCost(c, v);
    int pick = -1;
    for (std::size_t t = 0; t < seen.size(); ++t) {
      if (t > 0 && seen[t] == seen[t - 1]) continue;
      const double cost = cost_on(seen[t], v);
      if (cost < best) best = cost, pick = seen[t];
    }
    return pick;
  });
  // Then the outliers, one data cost under every label, take the label
  // most of their placed neighbours have (fewest boundary edges; ties to
  // the lowest id).
  grow([](std::size_t, const std::vector<int>& seen) {
    int pick = -1;
    std::ptrdiff_t most = 0;
    for (auto it = seen.begin(); it != seen.end();) {
      const auto end = std::upper_bound(it, seen.end(), *it);
      if (end - it > most) most = end - it, pick = *it;
      it = end;
    }
    return pick;
  });
  // The edges at r's vertices, before and after (each edge inside r once).
  DropLabeling out;
  for (std::size_t k = 0; k < n; ++k) {
    const int v = r.vertices[k];
    std::size_t e = first[k];
    for (const int u : c.graph.Neighbors(v)) {
      const long b = beside[e++];
      if (b >= 0 && u < v) continue;
      const bool before = b < 0;
      const bool after = next[k] != label_at(b);
      if (before != after) out.boundary_delta += (after ? 1.0 : -1.0) * EdgeCost(c, u, v);
    }
  }
  out.next = std::move(next);
  return out;
}

}  // namespace

DropMove DropDelta(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions, int id) {
  ReestimatedRegions as_given(c, regions, /*reestimate=*/false);
  return DropDelta(c, labels, as_given, id);
}

DropMove DropDelta(const SegmentContext& c, const std::vector<int>& labels,
                   ReestimatedRegions& region, int id) {
  const RegionState& r = region(id);
  DropMove move;
  DropLabeling labeling = DropLabels(c, labels, region, id);
  move.next = std::move(labeling.next);
  move.takers = move.next;
  std::sort(move.takers.begin(), move.takers.end());
  move.takers.erase(std::unique(move.takers.begin(), move.takers.end()), move.takers.end());
  if (!move.takers.empty() && move.takers.front() < 0) move.takers.erase(move.takers.begin());

  // Data and label costs: r's go, the outliers pay c_out / 2, each taker
  // pays for all it holds under its refitted surface.
  double delta = -region.Cost(id) - LabelCost(c, r);
  for (std::size_t k = 0; k < r.vertices.size(); ++k) {
    if (move.next[k] < 0) delta += OutlierCost(c, r.vertices[k]);
  }
  // The vertices each taker takes, in r's order, in one pass.
  std::vector<std::vector<int>> taken_by(move.takers.size());
  for (std::size_t k = 0; k < r.vertices.size(); ++k) {
    if (move.next[k] < 0) continue;
    const auto t = std::lower_bound(move.takers.begin(), move.takers.end(), move.next[k]);
    taken_by[t - move.takers.begin()].push_back(r.vertices[k]);
  }
  for (std::size_t t = 0; t < move.takers.size(); ++t) {
    const int o = move.takers[t];
    const RegionState& taker = region(o);
    const std::vector<int>& taken = taken_by[t];
    std::vector<int> grown(taker.vertices.size() + taken.size());
    std::merge(taker.vertices.begin(), taker.vertices.end(), taken.begin(), taken.end(),
               grown.begin());
    const double own = region.Cost(o);
    double cost = own + DataCost(c, taker.surface, taken);
    Surface surface = taker.surface;
    // The refit is taken only if it costs less than `cost`: a cost above
    // that need not be summed to the end. A surface sharing parameters with
    // a neighbour's fit keeps them (energy.h): only re-estimation frees it.
    if (taker.shared_parameters == 0) {
      const PricedFit fit = PriceFit(c, taker.type, grown, /*stop=*/cost);
      if (fit.surface && fit.cost < cost) cost = fit.cost, surface = *fit.surface;
    }
    delta += cost - own + LabelCost(c, taker, MeasuredCount(c, grown)) - LabelCost(c, taker);
    move.surfaces.push_back(surface);
  }

  delta += labeling.boundary_delta;
  move.delta = delta;
  return move;
}

}  // namespace meshseg::segment_internal
