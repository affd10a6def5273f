// Vertex adjacency in compressed rows and the metric neighbourhoods N(i, W)
// of seed 000 §2 (breadth-first over edges, cut by Euclidean radius).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "curvature/spatial_order.h"
#include "meshseg/curvature.h"

namespace meshseg {

namespace curvature_internal {

VertexGraph NumberedVertexGraph(const TriMesh& mesh, std::span<const int> order,
                                std::span<const int> rank) {
  // Two parallel passes over the vertices (valences, then the rows in the
  // order OpenMesh circulates them) around a prefix sum: each vertex's row
  // is the same as a serial build's.
  const bool renumbered = !order.empty();
  VertexGraph g;
  const int n = static_cast<int>(mesh.n_vertices());
  g.offsets.assign(n + 1, 0);
  g.positions.resize(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k < r.end(); ++k) {
      const TriMesh::VertexHandle vh(renumbered ? order[k] : k);
      g.positions[k] = ToEigen(mesh.point(vh));
      int valence = 0;
      for (auto it = mesh.cvv_iter(vh); it.is_valid(); ++it) ++valence;
      g.offsets[k + 1] = valence;
    }
  });
  for (int k = 0; k < n; ++k) g.offsets[k + 1] += g.offsets[k];
  g.neighbors.resize(g.offsets[n]);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k < r.end(); ++k) {
      int out = g.offsets[k];
      const TriMesh::VertexHandle vh(renumbered ? order[k] : k);
      for (auto it = mesh.cvv_iter(vh); it.is_valid(); ++it) {
        g.neighbors[out++] = renumbered ? rank[it->idx()] : it->idx();
      }
    }
  });
  return g;
}

}  // namespace curvature_internal

VertexGraph BuildVertexGraph(const TriMesh& mesh) {
  return curvature_internal::NumberedVertexGraph(mesh, {}, {});
}

void CollectNeighborhood(const VertexGraph& graph, int i, double radius,
                         std::span<const uint8_t> excluded, NeighborhoodScratch* scratch,
                         std::vector<int>* out, std::size_t max_count) {
  out->clear();
  if (scratch->mark.size() != graph.positions.size()) {
    scratch->mark.assign(graph.positions.size(), 0);
    scratch->stamp = 0;
  }
  if (++scratch->stamp == 0) {  // wrapped: clear the marks once
    std::fill(scratch->mark.begin(), scratch->mark.end(), 0);
    scratch->stamp = 1;
  }
  // Raw pointers: the compiler cannot prove that the pushes into `out` leave
  // the marks and positions alone, and would reload them on every edge.
  const uint32_t stamp = scratch->stamp;
  uint32_t* const mark = scratch->mark.data();
  const Eigen::Vector3d* const positions = graph.positions.data();
  const int* const offsets = graph.offsets.data();
  const int* const neighbors = graph.neighbors.data();
  const uint8_t* const skip = excluded.empty() ? nullptr : excluded.data();
  const double r2 = radius * radius;
  const Eigen::Vector3d center = positions[i];
  mark[i] = stamp;
  out->push_back(i);
  for (std::size_t head = 0; head < out->size(); ++head) {
    if (max_count != 0 && out->size() >= max_count) break;
    const int x = (*out)[head];
    for (int k = offsets[x], end = offsets[x + 1]; k < end; ++k) {
      const int j = neighbors[k];
      if (mark[j] == stamp) continue;
      mark[j] = stamp;
      if (skip != nullptr && skip[j] != 0) continue;
      if ((positions[j] - center).squaredNorm() >= r2) continue;
      out->push_back(j);
      if (max_count != 0 && out->size() >= max_count) break;
    }
  }
}

}  // namespace meshseg
