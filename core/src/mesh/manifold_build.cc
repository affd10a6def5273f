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

// Halfedge 3t+k of triangle t runs from corner k to corner k+1. Returns, per
// halfedge, the index of its twin (the same edge reversed) or -1 on the
// boundary; empty if a directed edge occurs twice. Needs 3 n < 2^31 (the
// readers' max_elements keeps n far below).
LargeVector<int> Twins(const LargeVector<std::array<int, 3>>& triangles, int vertex_count) {
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
  std::atomic<bool> repeated{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, vertex_count, 4096),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int v = range.begin(); v < range.end(); ++v) {
                        std::sort(out.begin() + start[v], out.begin() + start[v + 1]);
                        for (int k = start[v] + 1; k < start[v + 1]; ++k) {
                          if (out[k].first == out[k - 1].first) repeated = true;
                        }
                      }
                    });
  if (repeated) return {};
  LargeVector<int> twin(n, -1);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& range) {
    for (int h = range.begin(); h < range.end(); ++h) {
      const auto& t = triangles[h / 3];
      const int from = t[h % 3];
      const int to = t[(h % 3 + 1) % 3];
      const auto first = out.begin() + start[to];
      const auto last = out.begin() + start[to + 1];
      const auto it = std::lower_bound(first, last, std::make_pair(from, -1));
      if (it != last && it->first == from) twin[h] = it->second;
    }
  });
  return twin;
}

}  // namespace

bool BuildManifold(const LargeVector<std::array<int, 3>>& triangles, TriMesh* mesh) {
  TriMesh& m = *mesh;
  const int vertex_count = static_cast<int>(m.n_vertices());
  const LargeVector<int> twin = Twins(triangles, vertex_count);
  const int n = static_cast<int>(triangles.size()) * 3;
  if (twin.empty() && n > 0) return false;

  // One edge per input edge, numbered in order of the halfedge that reaches
  // it first; that halfedge is the edge's first OpenMesh halfedge (2e).
  LargeVector<HalfedgeHandle> handle(n);
  int edge_count = 0;
  for (int h = 0; h < n; ++h) {
    if (handle[h].is_valid()) continue;
    handle[h] = HalfedgeHandle(2 * edge_count);
    if (twin[h] >= 0) handle[twin[h]] = HalfedgeHandle(2 * edge_count + 1);
    ++edge_count;
  }
  // Sizes every item and property array once instead of per new_edge().
  m.resize(vertex_count, edge_count, triangles.size());
  LargeVector<HalfedgeHandle> boundary_out(vertex_count);  // outgoing boundary halfedge
  for (int h = 0; h < n; ++h) {
    const auto& t = triangles[h / 3];
    const TriMesh::VertexHandle from(t[h % 3]);
    const TriMesh::VertexHandle to(t[(h % 3 + 1) % 3]);
    m.set_vertex_handle(handle[h], to);
    if (twin[h] < 0) {
      const HalfedgeHandle outside = m.opposite_halfedge_handle(handle[h]);
      m.set_vertex_handle(outside, from);
      m.set_face_handle(outside, TriMesh::FaceHandle());
      boundary_out[to.idx()] = outside;  // runs to -> from, without a face
    }
  }
  for (size_t f = 0; f < triangles.size(); ++f) {
    const TriMesh::FaceHandle fh(static_cast<int>(f));
    const HalfedgeHandle* h = &handle[3 * f];
    // As add_face(): the face's halfedge ends at corner 0, so fv_range()
    // lists the corners in input order.
    m.set_halfedge_handle(fh, h[2]);
    for (int k = 0; k < 3; ++k) {
      m.set_face_handle(h[k], fh);
      m.set_next_halfedge_handle(h[k], h[(k + 1) % 3]);
      const TriMesh::VertexHandle from(triangles[f][k]);
      if (!m.halfedge_handle(from).is_valid()) m.set_halfedge_handle(from, h[k]);
    }
  }
  // A boundary vertex's halfedge is its outgoing boundary halfedge, and a
  // boundary halfedge to -> from continues with the one leaving `from` (one
  // per boundary vertex, as each vertex has a single fan).
  for (int v = 0; v < vertex_count; ++v) {
    const HalfedgeHandle b = boundary_out[v];
    if (!b.is_valid()) continue;
    m.set_halfedge_handle(TriMesh::VertexHandle(v), b);
    m.set_next_halfedge_handle(b, boundary_out[m.to_vertex_handle(b).idx()]);
  }
  return true;
}

}  // namespace meshseg::mesh_internal
