#include "pipeline/boundary_distance.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace meshseg::pipeline_internal {

std::vector<double> VertexBoundaryDistance(const TriMesh& mesh, std::span<const int> face_labels,
                                           double limit) {
  std::vector<double> distance(mesh.n_vertices(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;  // distance, vertex
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (const auto v : mesh.vertices()) {
    bool boundary = mesh.is_boundary(v);
    int label = 0;
    bool first = true;
    for (auto f = mesh.cvf_iter(v); f.is_valid() && !boundary; ++f) {
      const int l = face_labels[f->idx()];
      boundary = !first && l != label;
      label = l;
      first = false;
    }
    if (boundary) {
      distance[v.idx()] = 0.0;
      queue.emplace(0.0, v.idx());
    }
  }
  // Dijkstra from every boundary vertex at once.
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > distance[i]) continue;
    const TriMesh::VertexHandle v(i);
    for (auto h = mesh.cvoh_iter(v); h.is_valid(); ++h) {
      const TriMesh::VertexHandle w = mesh.to_vertex_handle(*h);
      const double through = d + static_cast<double>(mesh.calc_edge_length(*h));
      if (through < distance[w.idx()] && through < limit) {
        distance[w.idx()] = through;
        queue.emplace(through, w.idx());
      }
    }
  }
  return distance;
}

}  // namespace meshseg::pipeline_internal
