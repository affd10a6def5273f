// Vertex adjacency in compressed rows and the metric neighbourhoods N(i, W)
// of seed 000 §2 (breadth-first over edges, cut by Euclidean radius).
#include <algorithm>
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
  const std::size_t n = graph.positions.size();
  if (scratch->mark.size() != n) {
    scratch->mark.assign(n, 0);
    scratch->stamp = 0;
  }
  if (++scratch->stamp == 0) {  // wrapped: clear the marks once
    std::fill(scratch->mark.begin(), scratch->mark.end(), 0);
    scratch->stamp = 1;
  }
  // Raw pointers: the compiler cannot prove that the writes into the queue
  // leave the marks and positions alone, and would reload them on every edge.
  const uint32_t stamp = scratch->stamp;
  uint32_t* const mark = scratch->mark.data();
  const Eigen::Vector3d* const positions = graph.positions.data();
  const int* const offsets = graph.offsets.data();
  const int* const neighbors = graph.neighbors.data();
  const uint8_t* const skip = excluded.empty() ? nullptr : excluded.data();
  const double r2 = radius * radius;
  const Eigen::Vector3d center = positions[i];
  // The queue is written without branches: every neighbour of the row is
  // stored at the queue's end and kept (the end moves past it) only if it
  // is new, not excluded and inside the radius. Whether a neighbour is new
  // follows no pattern the branch predictor can learn (about half of a
  // row was reached before), so the branchy form waited on mispredictions.
  // Each row is still scanned in order and its kept vertices appended in
  // order: the same queue, so the same neighbourhood in the same order.
  std::vector<int>& queue = scratch->queue;
  if (queue.size() < 64) queue.resize(64);
  int* q = queue.data();
  std::size_t size = 0;
  mark[i] = stamp;
  q[size++] = i;
  const std::size_t cap = max_count == 0 ? n : max_count;
  for (std::size_t head = 0; head < size && size < cap; ++head) {
    const int x = q[head];
    const int begin = offsets[x];
    const int end = offsets[x + 1];
    const std::size_t need = size + static_cast<std::size_t>(end - begin);
    if (need > queue.size()) {
      queue.resize(std::max(need, 2 * queue.size()));
      q = queue.data();
    }
    for (int k = begin; k < end; ++k) {
      const int j = neighbors[k];
      // As the branchy form: a vertex seen before is neither taken nor
      // marked again; one newly seen is marked whether or not it is taken
      // (excluded vertices and those outside are not passed through). The
      // radius test is !(d >= r2), so a NaN distance is taken, as before.
      const bool fresh = mark[j] != stamp;
      mark[j] = stamp;
      const bool allowed = skip == nullptr || skip[j] == 0;
      const bool inside = !((positions[j] - center).squaredNorm() >= r2);
      q[size] = j;
      size += static_cast<std::size_t>(fresh & allowed & inside);
    }
  }
  // Vertices past the cap were appended by the last row scanned; the
  // first `cap` are those the one-at-a-time walk stops at.
  out->assign(q, q + std::min(size, cap));
}

}  // namespace meshseg
