#include <algorithm>
#include <numeric>

#include <tbb/parallel_invoke.h>

#include "meshseg/mesh.h"

namespace meshseg {
namespace {

int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Face-connected components: faces sharing an edge are connected.
int64_t ComponentCount(const TriMesh& tri) {
  std::vector<int> parent(tri.n_faces());
  std::iota(parent.begin(), parent.end(), 0);
  int64_t components = static_cast<int64_t>(tri.n_faces());
  for (const auto e : tri.edges()) {
    const auto f0 = tri.face_handle(tri.halfedge_handle(e, 0));
    const auto f1 = tri.face_handle(tri.halfedge_handle(e, 1));
    if (!f0.is_valid() || !f1.is_valid()) continue;
    const int r0 = Root(parent, f0.idx());
    const int r1 = Root(parent, f1.idx());
    if (r0 != r1) {
      parent[r1] = r0;
      --components;
    }
  }
  return components;
}

}  // namespace

double MeanEdgeLength(const TriMesh& mesh) {
  if (mesh.n_edges() == 0) return 0.0;
  double sum = 0.0;
  for (const auto e : mesh.edges()) sum += mesh.calc_edge_length(e);
  return sum / static_cast<double>(mesh.n_edges());
}

MeshStats MeshStatistics(const Mesh& mesh) {
  const TriMesh& tri = mesh.tri;
  MeshStats stats;
  stats.vertex_count = static_cast<int64_t>(tri.n_vertices());
  stats.face_count = static_cast<int64_t>(tri.n_faces());
  stats.input_vertex_count = mesh.input_vertex_count > 0 ? mesh.input_vertex_count
                                                          : stats.vertex_count;
  stats.input_face_count = mesh.face_of_input.empty()
                               ? stats.face_count
                               : static_cast<int64_t>(mesh.face_of_input.size());
  // Three independent passes side by side; each runs in its own order as
  // before (the edge-length sum in edge order), so the same values.
  tbb::parallel_invoke(
      [&] { stats.mean_edge_length = MeanEdgeLength(tri); },
      [&] { stats.component_count = ComponentCount(tri); },
      [&] {
        stats.dropped_face_count =
            std::count(mesh.face_of_input.begin(), mesh.face_of_input.end(), -1);
        if (tri.n_vertices() > 0) {
          stats.bbox_min = stats.bbox_max = ToEigen(tri.point(TriMesh::VertexHandle(0)));
        }
        for (const auto v : tri.vertices()) {
          const Eigen::Vector3d p = ToEigen(tri.point(v));
          stats.bbox_min = stats.bbox_min.cwiseMin(p);
          stats.bbox_max = stats.bbox_max.cwiseMax(p);
          stats.isolated_vertex_count += tri.is_isolated(v);
        }
        for (const auto e : tri.edges()) stats.boundary_edge_count += tri.is_boundary(e);
      });
  stats.non_manifold_edge_count = mesh.input_topology.non_manifold_edge_count;
  stats.non_manifold_vertex_count = mesh.input_topology.non_manifold_vertex_count;
  stats.degenerate_face_count = mesh.input_topology.degenerate_face_count;
  return stats;
}

}  // namespace meshseg
