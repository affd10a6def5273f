#include "segment/alpha_expansion.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/energy.h"

namespace meshseg::segment_internal {
namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using Graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<
        boost::edge_capacity_t, double,
        boost::property<boost::edge_residual_capacity_t, double,
                        boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>;

// Adds u->v with capacity `forward` and v->u with `backward`, each the
// other's reverse, as the max-flow needs.
void AddEdgePair(int u, int v, double forward, double backward, Graph* g) {
  auto capacity = boost::get(boost::edge_capacity, *g);
  auto reverse = boost::get(boost::edge_reverse, *g);
  const auto uv = boost::add_edge(u, v, *g).first;
  const auto vu = boost::add_edge(v, u, *g).first;
  capacity[uv] = forward;
  capacity[vu] = backward;
  reverse[uv] = vu;
  reverse[vu] = uv;
}

// D_v under label l (-1: unlabelled).
double LabelDataCost(const SegmentContext& c, const std::vector<RegionState>& regions, int v,
                     int l) {
  return l < 0 ? OutlierCost(c, v) : VertexCost(c, v, regions[l].surface);
}

// The vertices not labelled `alpha` within `rings` mesh edges of a vertex
// labelled `alpha`, walked outward ring by ring (sorted).
std::vector<int> Band(const SegmentContext& c, const std::vector<int>& labels,
                      const RegionState& alpha_region, int alpha, int rings) {
  std::vector<int> band;
  std::unordered_set<int> visited;
  std::vector<int> ring;
  auto walk_from = [&](int v, std::vector<int>* into) {
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] != alpha && visited.insert(u).second) into->push_back(u);
    }
  };
  for (const int v : alpha_region.vertices) walk_from(v, &ring);
  for (int k = 1; k <= rings && !ring.empty(); ++k) {
    band.insert(band.end(), ring.begin(), ring.end());
    if (k == rings) break;
    std::vector<int> next;
    for (const int v : ring) walk_from(v, &next);
    ring.swap(next);
  }
  std::sort(band.begin(), band.end());
  return band;
}

}  // namespace

Expansion ExpandRegion(const SegmentContext& c, const std::vector<int>& labels,
                       const std::vector<RegionState>& regions, int alpha, int rings) {
  Expansion out;
  const std::vector<int> band = Band(c, labels, regions[alpha], alpha, rings);
  if (band.empty()) return out;
  const int n = static_cast<int>(band.size());
  auto node_of = [&](int v) {
    const auto it = std::lower_bound(band.begin(), band.end(), v);
    return it != band.end() && *it == v ? static_cast<int>(it - band.begin()) : -1;
  };
  // x_v = 1: v takes alpha. diff[k] = cost(x = 1) - cost(x = 0) of the
  // unary terms of band vertex k; the pairwise terms between two band
  // vertices as E(x_u, x_v) = A + (C - A) x_u + (D - C) x_v
  // + (B + C - A - D) (1 - x_u) x_v (Kolmogorov & Zabih, PAMI 2004).
  std::vector<double> diff(n, 0.0);
  std::vector<double> data_change(n, 0.0);
  Graph g(n + 2);
  const int source = n;  // source side: x = 0, keep the label
  const int sink = n + 1;
  for (int k = 0; k < n; ++k) {
    const int v = band[k];
    const int lv = labels[v];
    data_change[k] = VertexCost(c, v, regions[alpha].surface) - LabelDataCost(c, regions, v, lv);
    diff[k] += data_change[k];
    for (const int u : c.graph.Neighbors(v)) {
      const int lu = labels[u];
      const double w = EdgeCost(c, u, v);
      const int j = lu == alpha ? -1 : node_of(u);
      if (j < 0) {
        // A fixed neighbour: the edge costs w [l != l_u] under v's label l.
        diff[k] += w * ((lu != alpha) - (lv != lu));
      } else if (j > k) {
        // A = w [l_v != l_u], B = C = w (neither is alpha), D = 0.
        const double a = lv != lu ? w : 0.0;
        diff[k] += w - a;  // C - A on x_v
        diff[j] -= w;      // D - C on x_u
        const double pair = 2.0 * w - a;  // cut when x_v = 0 and x_u = 1
        if (pair > 0.0) AddEdgePair(k, j, pair, 0.0, &g);
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    // An edge from the source is cut when x = 1, one to the sink when x = 0.
    if (diff[k] > 0.0) {
      AddEdgePair(source, k, diff[k], 0.0, &g);
    } else if (diff[k] < 0.0) {
      AddEdgePair(k, sink, -diff[k], 0.0, &g);
    }
  }
  std::vector<boost::default_color_type> color(n + 2);
  std::vector<Traits::edge_descriptor> predecessor(n + 2);
  std::vector<long> distance(n + 2);
  const auto index = boost::get(boost::vertex_index, g);
  boost::boykov_kolmogorov_max_flow(
      g, boost::get(boost::edge_capacity, g), boost::get(boost::edge_residual_capacity, g),
      boost::get(boost::edge_reverse, g),
      boost::make_iterator_property_map(predecessor.begin(), index),
      boost::make_iterator_property_map(color.begin(), index),
      boost::make_iterator_property_map(distance.begin(), index), index, source, sink);
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
    ++size_change[alpha];
    if (lv >= 0) --size_change[lv];
    for (const int u : c.graph.Neighbors(v)) {
      const int lu = labels[u];
      const int j = lu == alpha ? -1 : node_of(u);
      const bool u_takes = j >= 0 && takes[j];
      if (u_takes && u < v) continue;  // counted from u
      const bool before = lv != lu;
      const bool after = alpha != (u_takes ? alpha : lu);
      if (before != after) change += (after ? 1.0 : -1.0) * EdgeCost(c, u, v);
    }
  }
  out.smooth_data_delta = change;
  for (const auto& [r, dn] : size_change) {
    const long size = static_cast<long>(regions[r].vertices.size());
    change += LabelCost(c, regions[r].type, static_cast<std::size_t>(size + dn)) -
              LabelCost(c, regions[r].type, static_cast<std::size_t>(size));
  }
  out.delta = change;
  return out;
}

absl::StatusOr<int> ExpandRegions(const SegmentContext& c, std::vector<int>* labels,
                                  std::vector<RegionState>* regions, int rings) {
  int moved = 0;
  const int count = static_cast<int>(regions->size());
  for (int sweep = 0; sweep < kMaxExpansionSweeps; ++sweep) {
    std::vector<uint8_t> changed(count, 0);
    int moved_now = 0;
    for (int alpha = 0; alpha < count; ++alpha) {
      MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
      if (!(*regions)[alpha].alive || (*regions)[alpha].vertices.empty()) continue;
      const Expansion move = ExpandRegion(c, *labels, *regions, alpha, rings);
      if (move.taken.empty() || !(move.delta < 0.0)) continue;
      // The vertices each region gives up, then the labels.
      std::map<int, std::vector<int>> given;
      for (const int v : move.taken) {
        if ((*labels)[v] >= 0) given[(*labels)[v]].push_back(v);
        (*labels)[v] = alpha;
      }
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
  }
  return moved;
}

}  // namespace meshseg::segment_internal
