#include "segment/region_graph.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The vertices of live regions with a neighbour in another live region, in
// ascending order. Each vertex is tested on its own (it reads only labels),
// side by side; the few found are summed in vertex order, as a walk over
// every vertex would.
std::vector<int> BoundaryVertices(const SegmentContext& c, const std::vector<int>& labels,
                                  const std::vector<RegionState>& regions) {
  const auto live = [&](int l) { return l >= 0 && regions[l].alive; };
  const int n = c.vertex_count();
  constexpr int kBlock = 1 << 14;
  const int blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::vector<int>> found(blocks);
  tbb::parallel_for(0, blocks, [&](int b) {
    for (int v = b * kBlock; v < std::min(n, (b + 1) * kBlock); ++v) {
      const int a = labels[v];
      if (!live(a)) continue;
      for (const int j : c.graph.Neighbors(v)) {
        if (labels[j] != a && live(labels[j])) {
          found[b].push_back(v);
          break;
        }
      }
    }
  });
  std::vector<int> out;
  for (const std::vector<int>& part : found) out.insert(out.end(), part.begin(), part.end());
  return out;
}

}  // namespace

std::vector<RegionArc> BuildRegionGraph(const SegmentContext& c, const std::vector<int>& labels,
                                        const std::vector<RegionState>& regions) {
  // Sum of normals of the boundary vertices of `from` next to `to`, each
  // vertex once per neighbouring region.
  std::map<std::pair<int, int>, Eigen::Vector3d> strip;
  std::vector<int> seen;
  for (const int v : BoundaryVertices(c, labels, regions)) {
    const int a = labels[v];
    if (a < 0 || !regions[a].alive) continue;
    seen.clear();
    for (const int j : c.graph.Neighbors(v)) {
      const int b = labels[j];
      if (b < 0 || b == a || !regions[b].alive || std::find(seen.begin(), seen.end(), b) != seen.end()) continue;
      seen.push_back(b);
      auto [it, inserted] = strip.try_emplace({a, b}, Eigen::Vector3d::Zero());
      it->second += c.normal(v);
    }
  }
  std::vector<RegionArc> arcs;
  for (const auto& [key, sum_ab] : strip) {
    const auto [a, b] = key;
    if (a > b) continue;
    const auto other = strip.find({b, a});
    if (other == strip.end()) continue;
    RegionArc arc{.a = a, .b = b};
    const double na = sum_ab.norm();
    const double nb = other->second.norm();
    const double cosine = na > 0.0 && nb > 0.0 ? sum_ab.dot(other->second) / (na * nb) : -1.0;
    arc.angle_deg = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / kPi;
    arc.smooth = arc.angle_deg < kSharpBoundaryDeg;
    arcs.push_back(arc);
  }
  return arcs;
}

absl::StatusOr<int> MergeBestPairs(
    const SegmentContext& c, std::vector<int>* labels, std::vector<RegionState>* regions,
    const std::function<bool(const RegionArc&)>& eligible,
    const std::function<std::optional<PairMerge>(int a, int b)>& test,
    const std::function<void(std::span<const std::pair<int, int>>)>& prepare) {
  std::map<std::pair<int, int>, std::optional<PairMerge>> cache;
  int merges = 0;
  std::vector<std::pair<int, int>> untested;
  while (true) {
    MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
    const std::vector<RegionArc> arcs = BuildRegionGraph(c, *labels, *regions);
    if (prepare) {
      untested.clear();
      for (const RegionArc& arc : arcs) {
        if (eligible(arc) && !cache.contains({arc.a, arc.b})) untested.emplace_back(arc.a, arc.b);
      }
      if (!untested.empty()) prepare(untested);
    }
    const RegionArc* best_arc = nullptr;
    const PairMerge* best = nullptr;
    for (const RegionArc& arc : arcs) {
      if (!eligible(arc)) continue;
      auto it = cache.find({arc.a, arc.b});
      if (it == cache.end()) it = cache.emplace(std::pair{arc.a, arc.b}, test(arc.a, arc.b)).first;
      if (!it->second) continue;
      if (best == nullptr || it->second->score > best->score) {
        best = &*it->second;
        best_arc = &arc;
      }
    }
    if (best == nullptr) return merges;
    const int a = best_arc->a;
    const int b = best_arc->b;
    const bool a_larger = (*regions)[a].vertices.size() >= (*regions)[b].vertices.size();
    const int into = a_larger ? a : b;
    const PairMerge merge = *best;
    MergeInto(into, a_larger ? b : a, labels, regions);
    (*regions)[into].type = merge.type;
    (*regions)[into].surface = merge.surface;
    (*regions)[into].shared_parameters = 0;  // the union is fitted free
    ++merges;
    std::erase_if(cache, [&](const auto& e) {
      return e.first.first == a || e.first.second == a || e.first.first == b ||
             e.first.second == b;
    });
  }
}

}  // namespace meshseg::segment_internal
