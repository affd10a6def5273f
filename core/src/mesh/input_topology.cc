#include "mesh/input_topology.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::mesh_internal {
namespace {

// Kept triangles around each vertex, in triangle order (compressed rows).
struct Incidence {
  LargeVector<int64_t> start;  // vertex_count + 1
  LargeVector<int> triangle;
};

Incidence IncidenceOf(int vertex_count, const LargeVector<std::array<int, 3>>& triangles,
                      const LargeVector<uint8_t>& keep) {
  Incidence inc;
  inc.start.assign(vertex_count + 1, 0);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    for (int v : triangles[t]) ++inc.start[v + 1];
  }
  std::partial_sum(inc.start.begin(), inc.start.end(), inc.start.begin());
  inc.triangle.resize(inc.start.back());
  LargeVector<int64_t> next(inc.start.begin(), inc.start.end() - 1);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    for (int v : triangles[t]) inc.triangle[next[v]++] = static_cast<int>(t);
  }
  return inc;
}

int Root(std::vector<int>& parent, int j) {
  while (parent[j] != j) j = parent[j] = parent[parent[j]];
  return j;
}

// Marks in *duplicate the triangles at v (as smallest vertex) that repeat the
// vertex set of an earlier one.
void MarkDuplicatesAt(int v, const Incidence& inc, const LargeVector<std::array<int, 3>>& tris,
                      std::vector<std::array<int, 3>>& scratch, LargeVector<uint8_t>* duplicate) {
  scratch.clear();
  for (int64_t k = inc.start[v]; k < inc.start[v + 1]; ++k) {
    std::array<int, 3> s = tris[inc.triangle[k]];
    std::sort(s.begin(), s.end());
    if (s[0] == v) scratch.push_back({s[1], s[2], inc.triangle[k]});
  }
  std::sort(scratch.begin(), scratch.end());
  for (size_t k = 1; k < scratch.size(); ++k) {
    if (scratch[k][0] == scratch[k - 1][0] && scratch[k][1] == scratch[k - 1][1]) {
      (*duplicate)[scratch[k][2]] = 1;
    }
  }
}

// Returns {non-manifold edges (v, w) with w > v, fans at v}.
std::pair<int, int> CountAt(int v, const Incidence& inc,
                            const LargeVector<std::array<int, 3>>& tris,
                            std::vector<std::pair<int, int>>& scratch,
                            std::vector<int>& parent) {
  scratch.clear();
  const int64_t begin = inc.start[v];
  const int n = static_cast<int>(inc.start[v + 1] - begin);
  for (int j = 0; j < n; ++j) {
    for (int w : tris[inc.triangle[begin + j]]) {
      if (w != v) scratch.emplace_back(w, j);
    }
  }
  std::sort(scratch.begin(), scratch.end());
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), 0);
  int fans = n;
  int non_manifold_edges = 0;
  for (size_t a = 0; a < scratch.size();) {
    size_t b = a + 1;
    while (b < scratch.size() && scratch[b].first == scratch[a].first) ++b;
    if (scratch[a].first > v && b - a > 2) ++non_manifold_edges;
    for (size_t k = a + 1; k < b; ++k) {
      const int ra = Root(parent, scratch[a].second);
      const int rk = Root(parent, scratch[k].second);
      if (ra != rk) {
        parent[rk] = ra;
        --fans;
      }
    }
    a = b;
  }
  return {non_manifold_edges, fans};
}

}  // namespace

TopologyCounts AnalyzeInputTopology(int vertex_count,
                                    const LargeVector<std::array<int, 3>>& triangles,
                                    LargeVector<uint8_t>* keep) {
  const Incidence inc = IncidenceOf(vertex_count, triangles, *keep);
  LargeVector<uint8_t> duplicate(triangles.size(), 0);
  LargeVector<int> edges_at(vertex_count, 0);
  LargeVector<uint8_t> pinched(vertex_count, 0);
  // Each slot is written by one vertex: duplicate[t] by t's smallest vertex.
  tbb::parallel_for(tbb::blocked_range<int>(0, vertex_count, 4096),
                    [&](const tbb::blocked_range<int>& r) {
    std::vector<std::array<int, 3>> sorted;
    std::vector<std::pair<int, int>> links;
    std::vector<int> parent;
    for (int v = r.begin(); v < r.end(); ++v) {
      MarkDuplicatesAt(v, inc, triangles, sorted, &duplicate);
      const auto [edges, fans] = CountAt(v, inc, triangles, links, parent);
      edges_at[v] = edges;
      pinched[v] = fans > 1;
    }
  });
  TopologyCounts counts;
  for (int v = 0; v < vertex_count; ++v) {
    counts.non_manifold_edge_count += edges_at[v];
    counts.non_manifold_vertex_count += pinched[v];
  }
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (duplicate[t]) {
      (*keep)[t] = 0;
      ++counts.duplicate_face_count;
    }
  }
  return counts;
}

}  // namespace meshseg::mesh_internal
