#include "reconstruct/graph_cut.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include "mesh/union_find.h"
#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: graph cut";

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using Graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<
        boost::edge_capacity_t, double,
        boost::property<boost::edge_residual_capacity_t, double,
                        boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>;

// Adds u→v with capacity `forward` and v→u with `backward`, each the
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

}  // namespace

absl::StatusOr<std::vector<uint8_t>> GraphCutLabels(const TetMesh& tets,
                                                    const std::vector<Eigen::Vector3d>& position,
                                                    const std::vector<double>& f, double k,
                                                    const std::vector<uint8_t>& resolved,
                                                    const std::vector<uint8_t>& seen_outside,
                                                    const RunContext& ctx) {
  const int n = static_cast<int>(position.size());
  std::vector<double> length_sum(n, 0.0);
  std::vector<int> degree(n, 0);
  double max_weight = 0.0;
  Graph g(n + 2);
  const int source = n;
  const int sink = n + 1;
  for (const auto& [a, b] : tets.edges) {
    const double len = (position[a] - position[b]).norm();
    length_sum[a] += len;
    length_sum[b] += len;
    ++degree[a];
    ++degree[b];
    const double w = std::abs(f[a] + f[b]) / std::max(len, 1e-300);  // eq. (10)
    max_weight = std::max(max_weight, w);
    AddEdgePair(a, b, w, w, &g);
  }
  std::vector<double> terminal(n);
  for (int v = 0; v < n; ++v) {
    const double ave = degree[v] > 0 ? length_sum[v] / degree[v] : 1.0;
    terminal[v] = k * std::abs(f[v]) / std::max(ave, 1e-300);  // eqs. (8)-(9)
    max_weight = std::max(max_weight, terminal[v]);
  }
  const double unbreakable = 1e6 * (max_weight + 1.0) * (tets.edges.size() + 1);
  for (int v = 0; v < n; ++v) {
    // A vertex whose side the points resolve is tied to it as firmly as the
    // hull is to the outside: the cut decides only the others.
    const bool fixed = !resolved.empty() && resolved[v];
    if (tets.on_hull[v] || (!seen_outside.empty() && seen_outside[v])) {
      AddEdgePair(v, sink, unbreakable, 0.0, &g);
    } else if (f[v] >= 0) {
      AddEdgePair(source, v, fixed ? unbreakable : terminal[v], 0.0, &g);
    } else {
      AddEdgePair(v, sink, fixed ? unbreakable : terminal[v], 0.0, &g);
    }
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  std::vector<boost::default_color_type> color(n + 2);
  std::vector<Traits::edge_descriptor> predecessor(n + 2);
  std::vector<int64_t> distance(n + 2);
  const auto index = boost::get(boost::vertex_index, g);
  boost::boykov_kolmogorov_max_flow(
      g, boost::get(boost::edge_capacity, g), boost::get(boost::edge_residual_capacity, g),
      boost::get(boost::edge_reverse, g),
      boost::make_iterator_property_map(predecessor.begin(), index),
      boost::make_iterator_property_map(color.begin(), index),
      boost::make_iterator_property_map(distance.begin(), index), index, source, sink);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  std::vector<uint8_t> inside(n);
  for (int v = 0; v < n; ++v) {
    inside[v] = color[v] == boost::color_traits<boost::default_color_type>::black() ? 1 : 0;
  }
  return inside;
}

std::vector<uint8_t> ResolvedInside(const TetMesh& tets, const std::vector<double>& f,
                                    const std::vector<uint8_t>& sparse, double epsilon) {
  const int n = static_cast<int>(f.size());
  std::vector<uint8_t> resolved(n);
  for (int v = 0; v < n; ++v) resolved[v] = ResolvedAt(tets, f, sparse, epsilon, v);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : tets.edges) {
    if (!resolved[a] || !resolved[b]) continue;
    const int ra = mesh_internal::FindRoot(parent, a), rb = mesh_internal::FindRoot(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<int> size(n, 0);
  int largest = -1;
  for (int v = 0; v < n; ++v) {
    if (!resolved[v]) continue;
    const int r = mesh_internal::FindRoot(parent, v);
    ++size[r];
    if (largest < 0 || size[r] > size[largest]) largest = r;
  }
  for (int v = 0; v < n; ++v) {
    resolved[v] = resolved[v] && mesh_internal::FindRoot(parent, v) == largest;
  }
  return resolved;
}

std::vector<uint8_t> SeenFromOutside(const TetMesh& tets, const std::vector<Support>& supports,
                                     const std::vector<double>& f, const FitInput& in) {
  const size_t n = tets.support.size();
  std::vector<uint8_t> outside(n, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    std::vector<std::pair<uint32_t, double>> found;
    for (size_t v = range.begin(); v != range.end(); ++v) {
      if (tets.on_hull[v] || !(f[v] > 0)) continue;
      const Support& s = supports[tets.support[v]];
      in.index.WithinRadiusUnordered(s.center, s.radius, &found);
      bool in_front = !found.empty();
      for (const auto& [j, unused] : found) {
        if (!((s.center - in.points[j]).dot(in.normals[j]) < -in.epsilon)) {
          in_front = false;
          break;
        }
      }
      outside[v] = in_front;
    }
  });
  return outside;
}

std::vector<uint8_t> SignLabels(const TetMesh& tets, const std::vector<double>& f) {
  std::vector<uint8_t> inside(f.size());
  for (size_t v = 0; v < f.size(); ++v) inside[v] = !tets.on_hull[v] && f[v] >= 0 ? 1 : 0;
  return inside;
}

}  // namespace meshseg::reconstruct_internal
