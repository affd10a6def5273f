#include "reconstruct/handle_strips.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "mesh/union_find.h"
#include "reconstruct/handle_loops.h"
#include "reconstruct/hole_width.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

// Whether `strip` (sorted faces) is an annulus whose removal leaves two
// border loops and no pinched vertex: connected, Euler characteristic 0,
// two border loops, each border vertex on exactly two border edges. Then
// cutting it along a non-separating loop lowers the genus by one.
bool IsAnnulus(const MeshGraph& g, const std::vector<int>& strip) {
  const auto in_strip = [&](int f) {
    return f >= 0 && std::binary_search(strip.begin(), strip.end(), f);
  };
  absl::flat_hash_map<int, int> border_degree;  // per vertex of the strip
  absl::flat_hash_set<int> edges;
  std::vector<std::pair<int, int>> border;
  std::vector<int> parent(strip.size());
  for (size_t i = 0; i < strip.size(); ++i) parent[i] = static_cast<int>(i);
  for (size_t i = 0; i < strip.size(); ++i) {
    const int f = strip[i];
    for (int k = 0; k < 3; ++k) {
      const int e = g.face_edges[f][k];
      const int u = g.face_vertices[f][k], v = g.face_vertices[f][(k + 2) % 3];
      border_degree.try_emplace(u, 0);
      if (!edges.insert(e).second) continue;
      const int other = g.edge_faces[e][0] == f ? g.edge_faces[e][1] : g.edge_faces[e][0];
      if (in_strip(other)) {
        const int j =
            static_cast<int>(std::lower_bound(strip.begin(), strip.end(), other) - strip.begin());
        parent[FindRoot(parent, static_cast<int>(i))] = FindRoot(parent, j);
      } else {
        ++border_degree[u];
        ++border_degree[v];
        border.push_back({u, v});
      }
    }
  }
  for (size_t i = 0; i < strip.size(); ++i) {
    if (FindRoot(parent, static_cast<int>(i)) != FindRoot(parent, 0)) return false;
  }
  for (const auto& [v, d] : border_degree) {
    if (d != 0 && d != 2) return false;
  }
  const int64_t chi = static_cast<int64_t>(border_degree.size()) -
                      static_cast<int64_t>(edges.size()) + static_cast<int64_t>(strip.size());
  if (chi != 0) return false;
  // Border loops: components of the border edges (each vertex on two).
  absl::flat_hash_map<int, int> loop_parent;
  for (const auto& [u, v] : border) {
    loop_parent.try_emplace(u, u);
    loop_parent.try_emplace(v, v);
  }
  const auto find = [&](int a) {
    while (loop_parent[a] != a) a = loop_parent[a] = loop_parent[loop_parent[a]];
    return a;
  };
  for (const auto& [u, v] : border) loop_parent[find(u)] = find(v);
  int loops = 0;
  for (const auto& [v, p] : loop_parent) loops += find(v) == v;
  return loops == 2;
}

// Faces with a vertex on `vertices`, sorted.
std::vector<int> StarOf(const MeshGraph& g, const std::vector<int>& vertices) {
  std::vector<int> star;
  for (const int v : vertices) {
    for (int k = g.faces_begin[v]; k < g.faces_begin[v + 1]; ++k) star.push_back(g.faces[k]);
  }
  std::sort(star.begin(), star.end());
  star.erase(std::unique(star.begin(), star.end()), star.end());
  return star;
}

// Whether the faces around `strip` (with `removed` already cut) stay
// connected to each other without it: the strip's loop does not separate.
// A search grows from every face next to the strip at once, in turns, and
// fronts that meet merge; the answer is known when one front is left (no
// separation) or a front runs out of faces (it closed off a side), so a
// loop that cuts off a small piece costs that piece, not the surface.
bool StripKeepsSurfaceConnected(const MeshGraph& g, const std::vector<uint8_t>& removed,
                                const std::vector<int>& strip, std::vector<uint32_t>* seen,
                                std::vector<int>* owner, uint32_t stamp) {
  const uint32_t visit = stamp + 1;
  for (const int f : strip) (*seen)[f] = stamp;  // blocked
  std::vector<std::vector<int>> front;
  std::vector<int> parent;
  for (const int f : strip) {
    for (const int e : g.face_edges[f]) {
      for (const int o : g.edge_faces[e]) {
        if (o < 0 || removed[o] || (*seen)[o] == stamp || (*seen)[o] == visit) continue;
        (*seen)[o] = visit;
        (*owner)[o] = static_cast<int>(front.size());
        parent.push_back(static_cast<int>(front.size()));
        front.push_back({o});
      }
    }
  }
  int groups = static_cast<int>(front.size());
  if (groups == 0) return false;
  while (groups > 1) {
    for (int i = 0; i < static_cast<int>(front.size()) && groups > 1; ++i) {
      if (FindRoot(parent, i) != i) continue;
      if (front[i].empty()) return false;  // a side closed off
      const int f = front[i].back();
      front[i].pop_back();
      for (const int e : g.face_edges[f]) {
        for (const int o : g.edge_faces[e]) {
          if (o < 0 || removed[o] || (*seen)[o] == stamp) continue;
          const int here = FindRoot(parent, i);
          if ((*seen)[o] == visit) {
            int a = here, b = FindRoot(parent, (*owner)[o]);
            if (a == b) continue;
            if (front[a].size() < front[b].size()) std::swap(a, b);
            front[a].insert(front[a].end(), front[b].begin(), front[b].end());
            front[b].clear();
            parent[b] = a;
            --groups;
            continue;
          }
          (*seen)[o] = visit;
          (*owner)[o] = here;
          front[here].push_back(o);
        }
      }
    }
  }
  return true;
}

}  // namespace

bool HoleAtMost(const TriMesh& tri, const std::vector<int>& loop, double width,
                const ScanPoints& scan) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(loop.size());
  for (const int v : loop) points.push_back(ToEigen(tri.point(TriMesh::VertexHandle(v))));
  Clearance to_scan;
  if (scan.points != nullptr && scan.index != nullptr && !scan.points->empty()) {
    to_scan = [&scan](const Eigen::Vector3d& q) {
      return ((*scan.points)[scan.index->Closest(q)] - q).norm();
    };
  }
  return HoleWidth(points, width / kWidthSteps, width, to_scan) <= width;
}

HandleStrips ShortHandleStrips(const TriMesh& tri, const std::vector<double>& max_loop, int genus,
                               const std::vector<uint8_t>& near,
                               const std::vector<double>& max_width, const ScanPoints& scan) {
  HandleStrips out;
  out.cut.assign(tri.n_faces(), 0);
  if (genus <= 0 || tri.n_faces() == 0) return out;
  const MeshGraph g = MakeMeshGraph(tri);
  const std::vector<HandleLoop> loops = ShortLoops(g, max_loop, near);
  out.loop_count = static_cast<int64_t>(loops.size());
  // 0 free, 1 on a cut strip, 2 on a loop found to separate.
  std::vector<uint8_t> state(tri.n_vertices(), 0);
  std::vector<uint8_t> on_border(tri.n_vertices(), 0);
  for (size_t v = 0; v + 1 < g.ring_begin.size(); ++v) {
    for (int k = g.ring_begin[v]; k < g.ring_begin[v + 1]; ++k) {
      const auto& faces = g.edge_faces[g.edge[k]];
      on_border[v] |= faces[0] < 0 || faces[1] < 0;
    }
  }
  std::vector<uint32_t> seen(tri.n_faces(), 0);
  std::vector<int> owner(tri.n_faces(), 0);
  uint32_t stamp = 1;
  std::vector<int> strip;
  for (const HandleLoop& loop : loops) {
    if (out.cut_count >= genus || out.check_count >= kMaxLoopChecks) break;
    int on_cut = 0, on_separating = 0;
    for (const int v : loop.vertices) {
      on_cut += state[v] == 1;
      on_separating += state[v] == 2;
    }
    // A loop through a cut is left for the next round; one lying mostly on a
    // loop that separates is that loop slid along the surface.
    if (on_cut > 0 || 2 * on_separating >= static_cast<int>(loop.vertices.size())) continue;
    if (!max_width.empty()) {
      double mean_width = 0.0;
      for (const int v : loop.vertices) mean_width += max_width[v];
      mean_width /= static_cast<double>(loop.vertices.size());
      if (loop.length > M_PI * mean_width && !HoleAtMost(tri, loop.vertices, mean_width, scan)) {
        continue;
      }
    }
    // The loop's star, grown by a ring while it is not an annulus (a loop
    // of a few edges through a tunnel as short as itself).
    strip = StarOf(g, loop.vertices);
    for (int ring = 0; ring < kMaxStripGrowth && !IsAnnulus(g, strip); ++ring) {
      std::vector<int> vertices;
      for (const int f : strip)
        vertices.insert(vertices.end(), g.face_vertices[f].begin(), g.face_vertices[f].end());
      strip = StarOf(g, vertices);
    }
    if (!IsAnnulus(g, strip)) continue;
    // Nor may it touch a border (a surface left open): a strip along a
    // border widens the hole and only seems not to separate.
    bool touches_cut = false;
    for (const int f : strip) {
      for (const int v : g.face_vertices[f]) touches_cut |= state[v] == 1 || on_border[v];
    }
    if (touches_cut) continue;
    ++out.check_count;
    stamp += 3;
    const bool keeps = StripKeepsSurfaceConnected(g, out.cut, strip, &seen, &owner, stamp);
    if (!keeps) {
      for (const int v : loop.vertices) state[v] = 2;
      continue;
    }
    ++out.cut_count;
    for (const int f : strip) {
      out.cut[f] = 1;
      for (const int v : g.face_vertices[f]) state[v] = 1;
    }
  }
  return out;
}

}  // namespace meshseg::reconstruct_internal
