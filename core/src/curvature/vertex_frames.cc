#include "curvature/vertex_frames.h"

#include <vector>

#include <Eigen/Geometry>
#include <tbb/parallel_invoke.h>

namespace meshseg::curvature_internal {

VertexFrames ComputeVertexFrames(const TriMesh& mesh) {
  const std::size_t n = mesh.n_vertices();
  VertexFrames f;
  f.normal.assign(n, Eigen::Vector3d::Zero());
  f.mean_edge_length.assign(n, 0.0);
  f.area.assign(n, 0.0);
  // The face pass (normals, areas) and the edge pass (edge lengths) write
  // different arrays, so they run side by side; each sums in face / edge
  // order as a single serial pass would.
  std::vector<int> valence(n, 0);
  tbb::parallel_invoke(
      [&] {
        // Sum of face normals scaled by twice the face area = area weighting.
        for (const auto fh : mesh.faces()) {
          int idx[3];
          int k = 0;
          for (auto it = mesh.cfv_iter(fh); it.is_valid() && k < 3; ++it) idx[k++] = it->idx();
          if (k != 3) continue;
          const Eigen::Vector3d a = ToEigen(mesh.point(TriMesh::VertexHandle(idx[0])));
          const Eigen::Vector3d b = ToEigen(mesh.point(TriMesh::VertexHandle(idx[1])));
          const Eigen::Vector3d c = ToEigen(mesh.point(TriMesh::VertexHandle(idx[2])));
          const Eigen::Vector3d cross = (b - a).cross(c - a);
          const double third_area = cross.norm() / 6.0;
          for (const int v : idx) {
            f.normal[v] += cross;
            f.area[v] += third_area;
          }
        }
      },
      [&] {
        for (const auto eh : mesh.edges()) {
          const auto heh = mesh.halfedge_handle(eh, 0);
          const int a = mesh.from_vertex_handle(heh).idx();
          const int b = mesh.to_vertex_handle(heh).idx();
          const double len = mesh.calc_edge_length(eh);
          f.mean_edge_length[a] += len;
          f.mean_edge_length[b] += len;
          ++valence[a];
          ++valence[b];
        }
      });
  for (std::size_t v = 0; v < n; ++v) {
    const double len = f.normal[v].norm();
    if (len > 0.0) f.normal[v] /= len;
    if (valence[v] > 0) f.mean_edge_length[v] /= valence[v];
  }
  return f;
}

}  // namespace meshseg::curvature_internal
