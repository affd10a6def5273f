#include "segment/alpha_expansion.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/energy.h"
#include "segment/expansion_band.h"

namespace meshseg::segment_internal {
namespace {

// The flow network of one expansion, in compressed rows: a vertex's arcs
// are stored together in the order they were added, so the max-flow walks
// them as it would an adjacency list built by the same additions.
using FlowGraph = boost::compressed_sparse_row_graph<boost::directedS>;
using FlowArc = boost::graph_traits<FlowGraph>::edge_descriptor;

// Arcs added in pairs, each the other's reverse (arc i's is i ^ 1).
struct Arcs {
  std::vector<int> from;
  std::vector<int> to;
  std::vector<double> capacity;
  // u->v with capacity `forward` and v->u with `backward`.
  void AddPair(int u, int v, double forward, double backward) {
    from.insert(from.end(), {u, v});
    to.insert(to.end(), {v, u});
    capacity.insert(capacity.end(), {forward, backward});
  }
};

// D_v under label l (-1: unlabelled), with each label's SurfaceDistance
// made once, on first use, in `distance_of` (one slot per region).
double LabelDataCost(const SegmentContext& c, const std::vector<RegionState>& regions,
                     std::vector<std::optional<SurfaceDistance>>& distance_of, int v, int l) {
  if (l < 0) return OutlierCost(c, v);
  if (!distance_of[l]) distance_of[l].emplace(regions[l].surface);
  return VertexCost(c, v, *distance_of[l]);
}

// The minimum cut of the network `arcs` over `nodes` nodes between
// `source` and `sink` (Boykov-Kolmogorov): the color of every node (white:
// the sink's tree).
std::vector<boost::default_color_type> MinimumCut(const Arcs& arcs, int nodes, int source,
                                                  int sink) {
  // The arcs sorted by tail, stably: each node's arcs keep the order they
  // were added in.
  const std::size_t m = arcs.from.size();
  std::vector<std::size_t> start(nodes + 1, 0);
  for (const int u : arcs.from) ++start[u + 1];
  for (int u = 0; u < nodes; ++u) start[u + 1] += start[u];
  std::vector<std::size_t> at(m);
  for (std::size_t i = 0; i < m; ++i) at[i] = start[arcs.from[i]]++;
  std::vector<std::pair<std::size_t, std::size_t>> sorted(m);
  std::vector<double> capacity(m);
  std::vector<FlowArc> reverse(m);
  for (std::size_t i = 0; i < m; ++i) {
    sorted[at[i]] = {static_cast<std::size_t>(arcs.from[i]), static_cast<std::size_t>(arcs.to[i])};
    capacity[at[i]] = arcs.capacity[i];
    reverse[at[i]] = FlowArc(arcs.to[i], at[i ^ 1]);
  }
  const FlowGraph g(boost::edges_are_sorted, sorted.begin(), sorted.end(),
                    static_cast<std::size_t>(nodes));
  std::vector<double> residual(m);
  std::vector<boost::default_color_type> color(nodes);
  std::vector<FlowArc> predecessor(nodes);
  std::vector<long> distance(nodes);
  const auto index = boost::get(boost::vertex_index, g);
  const auto arc_index = boost::get(boost::edge_index, g);
  boost::boykov_kolmogorov_max_flow(
      g, boost::make_iterator_property_map(capacity.begin(), arc_index),
      boost::make_iterator_property_map(residual.begin(), arc_index),
      boost::make_iterator_property_map(reverse.begin(), arc_index),
      boost::make_iterator_property_map(predecessor.begin(), index),
      boost::make_iterator_property_map(color.begin(), index),
      boost::make_iterator_property_map(distance.begin(), index), index, source, sink);
  return color;
}

// ExpandRegion with the bands of `bands` (current with `labels`). If
// `read` is given (one flag per region and a last one for -1), flags every
// label the expansion reads: alpha and the labels of the band and of its
// vertices' neighbours.
Expansion Expand(const SegmentContext& c, const std::vector<int>& labels,
                 const std::vector<RegionState>& regions, int alpha, int rings,
                 ExpansionBands* bands, std::vector<uint8_t>* read = nullptr) {
  Expansion out;
  const std::vector<int> band = bands->Band(labels, alpha, rings);
  const int n = static_cast<int>(band.size());
  // The band's numbering released on every way out.
  struct Release {
    const std::vector<int>& band;
    ExpansionBands* bands;
    ~Release() { bands->Release(band); }
  } release{band, bands};
  if (band.empty()) return out;
  // x_v = 1: v takes alpha. diff[k] = cost(x = 1) - cost(x = 0) of the
  // unary terms of band vertex k; the pairwise terms between two band
  // vertices as E(x_u, x_v) = A + (C - A) x_u + (D - C) x_v
  // + (B + C - A - D) (1 - x_u) x_v (Kolmogorov & Zabih, PAMI 2004).
  std::vector<double> diff(n, 0.0);
  std::vector<double> data_change(n, 0.0);
  Arcs arcs;
  const int source = n;  // source side: x = 0, keep the label
  const int sink = n + 1;
  const SurfaceDistance alpha_distance(regions[alpha].surface);
  std::vector<std::optional<SurfaceDistance>> distance_of(regions.size());
  for (int k = 0; k < n; ++k) {
    const int v = band[k];
    const int lv = labels[v];
    if (read != nullptr) {
      (*read)[lv < 0 ? regions.size() : lv] = 1;
      for (const int u : c.graph.Neighbors(v)) {
        (*read)[labels[u] < 0 ? regions.size() : labels[u]] = 1;
      }
    }
    data_change[k] =
        VertexCost(c, v, alpha_distance) - LabelDataCost(c, regions, distance_of, v, lv);
    diff[k] += data_change[k];
    for (const int u : c.graph.Neighbors(v)) {
      const int lu = labels[u];
      const double w = EdgeCost(c, u, v);
      const int j = lu == alpha ? -1 : bands->Node(u);
      if (j < 0) {
        // A fixed neighbour: the edge costs w [l != l_u] under v's label l.
        diff[k] += w * ((lu != alpha) - (lv != lu));
      } else if (j > k) {
        // A = w [l_v != l_u], B = C = w (neither is alpha), D = 0.
        const double a = lv != lu ? w : 0.0;
        diff[k] += w - a;  // C - A on x_v
        diff[j] -= w;      // D - C on x_u
        const double pair = 2.0 * w - a;  // cut when x_v = 0 and x_u = 1
        if (pair > 0.0) arcs.AddPair(k, j, pair, 0.0);
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    // An arc from the source is cut when x = 1, one to the sink when x = 0.
    if (diff[k] > 0.0) {
      arcs.AddPair(source, k, diff[k], 0.0);
    } else if (diff[k] < 0.0) {
      arcs.AddPair(k, sink, -diff[k], 0.0);
    }
  }
  const std::vector<boost::default_color_type> color = MinimumCut(arcs, n + 2, source, sink);
  // The sink tree (white) is the smallest set of band vertices a minimum cut
  // gives alpha (free, grey, vertices cut either way at equal cost keep
  // their labels).
  std::vector<uint8_t> takes(n, 0);
  for (int k = 0; k < n; ++k) {
    if (color[k] != boost::color_traits<boost::default_color_type>::white()) continue;
    takes[k] = 1;
    out.taken.push_back(band[k]);
  }
  if (out.taken.empty()) return out;
  // The change of E, term by term on the labels before and after.
  std::map<int, long> size_change;
  double change = 0.0;
  for (int k = 0; k < n; ++k) {
    if (!takes[k]) continue;
    const int v = band[k];
    const int lv = labels[v];
    change += data_change[k];
    // Label costs count measured vertices only (energy.h).
    if (c.Measured(v)) {
      ++size_change[alpha];
      if (lv >= 0) --size_change[lv];
    }
    for (const int u : c.graph.Neighbors(v)) {
      const int lu = labels[u];
      const int j = lu == alpha ? -1 : bands->Node(u);
      const bool u_takes = j >= 0 && takes[j];
      if (u_takes && u < v) continue;  // counted from u
      const bool before = lv != lu;
      const bool after = alpha != (u_takes ? alpha : lu);
      if (before != after) change += (after ? 1.0 : -1.0) * EdgeCost(c, u, v);
    }
  }
  out.smooth_data_delta = change;
  for (const auto& [r, dn] : size_change) {
    const long size = static_cast<long>(MeasuredCount(c, regions[r].vertices));
    change += LabelCost(c, regions[r], static_cast<std::size_t>(size + dn)) -
              LabelCost(c, regions[r], static_cast<std::size_t>(size));
  }
  out.delta = change;
  return out;
}

}  // namespace

Expansion ExpandRegion(const SegmentContext& c, const std::vector<int>& labels,
                       const std::vector<RegionState>& regions, int alpha, int rings) {
  ExpansionBands bands(c, labels, static_cast<int>(regions.size()));
  return Expand(c, labels, regions, alpha, rings, &bands);
}

absl::StatusOr<int> ExpandRegions(const SegmentContext& c, std::vector<int>* labels,
                                  std::vector<RegionState>* regions, int rings) {
  int moved = 0;
  const int count = static_cast<int>(regions->size());
  ExpansionBands bands(c, *labels, count);
  // An expansion not made is made again only if something it read has
  // changed since: its result is a function of alpha's vertices (they fix
  // the band), the labels of the band and of its vertices' neighbours, and
  // the surfaces and sizes of those labels. Each label (the last slot: -1)
  // has a version, raised when it gains or loses a vertex or is
  // re-estimated; an expansion is kept with the versions of the labels it
  // read, and while they stand it would be the same expansion, not made.
  std::vector<long> version(count + 1, 0);
  auto slot = [&](int l) { return l < 0 ? count : l; };
  std::vector<std::vector<std::pair<int, long>>> not_made(count);
  std::vector<uint8_t> read(count + 1, 0);
  auto unchanged = [&](int alpha) {
    const std::vector<std::pair<int, long>>& kept = not_made[alpha];
    return !kept.empty() && std::all_of(kept.begin(), kept.end(), [&](const auto& lv) {
      return version[lv.first] == lv.second;
    });
  };
  for (int sweep = 0; sweep < kMaxExpansionSweeps; ++sweep) {
    std::vector<uint8_t> changed(count, 0);
    int moved_now = 0;
    for (int alpha = 0; alpha < count; ++alpha) {
      MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
      if (!(*regions)[alpha].alive || (*regions)[alpha].vertices.empty()) continue;
      if (unchanged(alpha)) continue;
      read[alpha] = 1;
      const Expansion move = Expand(c, *labels, *regions, alpha, rings, &bands, &read);
      not_made[alpha].clear();
      if (move.taken.empty() || !(move.delta < 0.0)) {
        for (int l = 0; l <= count; ++l) {
          if (read[l]) not_made[alpha].emplace_back(l, version[l]);
        }
        std::fill(read.begin(), read.end(), 0);
        continue;
      }
      std::fill(read.begin(), read.end(), 0);
      // The vertices each region gives up, then the labels.
      std::map<int, std::vector<int>> given;
      for (const int v : move.taken) {
        if ((*labels)[v] >= 0) given[(*labels)[v]].push_back(v);
        ++version[slot((*labels)[v])];
        (*labels)[v] = alpha;
      }
      ++version[alpha];
      for (const auto& [r, vertices] : given) {
        std::vector<int>& own = (*regions)[r].vertices;
        std::vector<int> rest;
        rest.reserve(own.size() - vertices.size());
        std::set_difference(own.begin(), own.end(), vertices.begin(), vertices.end(),
                            std::back_inserter(rest));
        own.swap(rest);
        changed[r] = 1;
      }
      std::vector<int>& grown = (*regions)[alpha].vertices;
      std::vector<int> merged(grown.size() + move.taken.size());
      std::merge(grown.begin(), grown.end(), move.taken.begin(), move.taken.end(), merged.begin());
      grown.swap(merged);
      changed[alpha] = 1;
      bands.Moved(move.taken);
      moved_now += static_cast<int>(move.taken.size());
    }
    moved += moved_now;
    if (moved_now == 0) break;
    // PEARL's re-estimation: each region reads only its own vertices.
    tbb::parallel_for(0, count, [&](int r) {
      RegionState& region = (*regions)[r];
      if (changed[r] && region.alive && !region.vertices.empty()) {
        region = Reestimated(c, region);
      }
    });
    for (int r = 0; r < count; ++r) version[r] += changed[r];
    bands.Regroup(*labels);
  }
  return moved;
}

absl::StatusOr<Placed> PlacedByExpansion(const SegmentContext& c, const std::vector<int>& labels,
                                         const std::vector<RegionState>& regions, int id,
                                         RegionState state) {
  Placed placed{.labels = labels, .regions = regions};
  placed.regions[id] = std::move(state);
  MESHSEG_RETURN_IF_ERROR(ExpandRegions(c, &placed.labels, &placed.regions).status());
  placed.energy = TotalEnergy(c, placed.labels, placed.regions);
  return placed;
}

}  // namespace meshseg::segment_internal
