#include "mesh/manifold_build.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::mesh_internal {
namespace {

using HalfedgeHandle = TriMesh::HalfedgeHandle;

// Halfedge 3t+k of triangle t runs from corner k to corner k+1.
struct HalfedgeLinks {
  LargeVector<int> twin;       // per halfedge: the same edge reversed, -1 on the boundary
  LargeVector<int> first_out;  // per vertex: its smallest outgoing halfedge, -1 if none
};

// The links of `triangles`' halfedges; `twin` empty if a directed edge occurs
// twice. Needs 3 n < 2^31 (the readers' max_elements keeps n far below).
HalfedgeLinks Links(const LargeVector<std::array<int, 3>>& triangles, int vertex_count) {
  const int n = static_cast<int>(triangles.size()) * 3;
  // Outgoing halfedges per vertex, sorted by target (compressed rows).
  LargeVector<int> start(vertex_count + 1, 0);
  for (const auto& t : triangles) {
    for (int v : t) ++start[v + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  LargeVector<std::pair<int, int>> out(n);  // (target, halfedge)
  LargeVector<int> next(start.begin(), start.end() - 1);
  for (int h = 0; h < n; ++h) {
    const auto& t = triangles[h / 3];
    out[next[t[h % 3]]++] = {t[(h % 3 + 1) % 3], h};
  }
  // Each vertex's row on its own, then each halfedge's lookup on its own
  // (independent; the pairs are distinct, so a row's sorted order is unique).
  HalfedgeLinks links;
  links.first_out.resize(vertex_count);
  std::atomic<bool> repeated{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, vertex_count, 4096),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int v = range.begin(); v < range.end(); ++v) {
                        std::sort(out.begin() + start[v], out.begin() + start[v + 1]);
                        int first = start[v] < start[v + 1] ? out[start[v]].second : -1;
                        for (int k = start[v] + 1; k < start[v + 1]; ++k) {
                          if (out[k].first == out[k - 1].first) repeated = true;
                          first = std::min(first, out[k].second);
                        }
                        links.first_out[v] = first;
                      }
                    });
  if (repeated) return {};
  links.twin.resize(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& range) {
    for (int h = range.begin(); h < range.end(); ++h) {
      const auto& t = triangles[h / 3];
      const int from = t[h % 3];
      const int to = t[(h % 3 + 1) % 3];
      const auto first = out.begin() + start[to];
      const auto last = out.begin() + start[to + 1];
      const auto it = std::lower_bound(first, last, std::make_pair(from, -1));
      links.twin[h] = it != last && it->first == from ? it->second : -1;
    }
  });
  return links;
}

// Numbers the edges in order of the halfedge that reaches each first (the
// one of a pair with the smaller index, or a boundary halfedge alone); that
// halfedge becomes the edge's first OpenMesh halfedge 2e, its twin 2e+1.
// The number of a first halfedge is the count of first halfedges before it:
// a prefix sum, taken over blocks side by side. Returns the edge count.
int NumberEdges(const LargeVector<int>& twin, LargeVector<HalfedgeHandle>* handle) {
  constexpr int kBlock = 1 << 16;
  const int n = static_cast<int>(twin.size());
  const int blocks = (n + kBlock - 1) / kBlock;
  const auto is_first = [&](int h) { return twin[h] < 0 || twin[h] > h; };
  std::vector<int> block_start(blocks + 1, 0);
  tbb::parallel_for(0, blocks, [&](int b) {
    int count = 0;
    for (int h = b * kBlock; h < std::min(n, (b + 1) * kBlock); ++h) count += is_first(h);
    block_start[b + 1] = count;
  });
  std::partial_sum(block_start.begin(), block_start.end(), block_start.begin());
  tbb::parallel_for(0, blocks, [&](int b) {
    int edge = block_start[b];
    for (int h = b * kBlock; h < std::min(n, (b + 1) * kBlock); ++h) {
      if (!is_first(h)) continue;
      (*handle)[h] = HalfedgeHandle(2 * edge);
      if (twin[h] >= 0) (*handle)[twin[h]] = HalfedgeHandle(2 * edge + 1);
      ++edge;
    }
  });
  return block_start[blocks];
}

}  // namespace

bool BuildManifold(const LargeVector<std::array<int, 3>>& triangles, TriMesh* mesh) {
  TriMesh& m = *mesh;
  const int vertex_count = static_cast<int>(m.n_vertices());
  const HalfedgeLinks links = Links(triangles, vertex_count);
  const LargeVector<int>& twin = links.twin;
  const int n = static_cast<int>(triangles.size()) * 3;
  if (twin.empty() && n > 0) return false;

  LargeVector<HalfedgeHandle> handle(n);
  const int edge_count = NumberEdges(twin, &handle);
  // Sizes every item and property array once instead of per new_edge().
  m.resize(vertex_count, edge_count, triangles.size());
  // Each face writes only its own halfedges (and the boundary halfedge
  // opposite one of them), so the faces are linked side by side. As
  // add_face(): the face's halfedge ends at corner 0, so fv_range() lists
  // the corners in input order.
  const int face_count = static_cast<int>(triangles.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, face_count, 4096),
                    [&](const tbb::blocked_range<int>& range) {
    for (int f = range.begin(); f < range.end(); ++f) {
      const TriMesh::FaceHandle fh(f);
      const HalfedgeHandle* h = &handle[3 * f];
      m.set_halfedge_handle(fh, h[2]);
      for (int k = 0; k < 3; ++k) {
        m.set_vertex_handle(h[k], TriMesh::VertexHandle(triangles[f][(k + 1) % 3]));
        m.set_face_handle(h[k], fh);
        m.set_next_halfedge_handle(h[k], h[(k + 1) % 3]);
        if (twin[3 * f + k] < 0) {
          const HalfedgeHandle outside = m.opposite_halfedge_handle(h[k]);
          m.set_vertex_handle(outside, TriMesh::VertexHandle(triangles[f][k]));
          m.set_face_handle(outside, TriMesh::FaceHandle());
        }
      }
    }
  });
  // A vertex's halfedge is its first outgoing one in input order; a
  // boundary vertex's is its outgoing boundary halfedge instead (set below).
  tbb::parallel_for(tbb::blocked_range<int>(0, vertex_count, 8192),
                    [&](const tbb::blocked_range<int>& range) {
    for (int v = range.begin(); v < range.end(); ++v) {
      const int h = links.first_out[v];
      if (h >= 0) m.set_halfedge_handle(TriMesh::VertexHandle(v), handle[h]);
    }
  });
  // The boundary halfedge opposite h (from -> to) runs to -> from without a
  // face and continues with the one leaving `from` (one per boundary vertex,
  // as each vertex has a single fan).
  LargeVector<HalfedgeHandle> boundary_out(vertex_count);  // outgoing boundary halfedge
  for (int h = 0; h < n; ++h) {
    if (twin[h] >= 0) continue;
    boundary_out[triangles[h / 3][(h % 3 + 1) % 3]] = m.opposite_halfedge_handle(handle[h]);
  }
  for (int v = 0; v < vertex_count; ++v) {
    const HalfedgeHandle b = boundary_out[v];
    if (!b.is_valid()) continue;
    m.set_halfedge_handle(TriMesh::VertexHandle(v), b);
    m.set_next_halfedge_handle(b, boundary_out[m.to_vertex_handle(b).idx()]);
  }
  return true;
}

}  // namespace meshseg::mesh_internal
