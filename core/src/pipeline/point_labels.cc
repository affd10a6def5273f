#include "pipeline/point_labels.h"

#include <algorithm>
#include <limits>

#include <tbb/parallel_for.h>

#include "mesh/point_index.h"
#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {
std::vector<int> PointLabels(const TriMesh& mesh, std::span<const int> face_labels,
                             std::span<const Eigen::Vector3d> points,
                             std::span<const uint8_t> is_outlier) {
  std::vector<int> labels(points.size(), -1);
  if (mesh.n_vertices() == 0) return labels;
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) vertices.push_back(ToEigen(mesh.point(v)));
  const mesh_internal::PointIndex index(vertices);
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t k) {
    if (!is_outlier.empty() && is_outlier[k]) return;
    const uint32_t nearest = index.Closest(points[k]);
    double best = std::numeric_limits<double>::infinity();
    for (auto f = mesh.cvf_iter(TriMesh::VertexHandle(static_cast<int>(nearest))); f.is_valid(); ++f) {
      auto v = mesh.cfv_iter(*f);
      const Eigen::Vector3d a = ToEigen(mesh.point(*v));
      const Eigen::Vector3d b = ToEigen(mesh.point(*++v));
      const Eigen::Vector3d c = ToEigen(mesh.point(*++v));
      const double d = SquaredDistanceToTriangle(points[k], a, b, c);
      if (d < best) {
        best = d;
        labels[k] = face_labels[f->idx()];
      }
    }
  });
  return labels;
}

}  // namespace meshseg::pipeline_internal
