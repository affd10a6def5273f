#include "pipeline/point_labels.h"

#include <algorithm>
#include <limits>

#include <nanoflann.hpp>
#include <tbb/parallel_for.h>

#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {
namespace {

// nanoflann dataset adaptor over the mesh's vertex positions.
struct VertexCloud {
  const TriMesh* mesh;
  size_t kdtree_get_point_count() const { return mesh->n_vertices(); }
  double kdtree_get_pt(size_t i, size_t dim) const {
    return mesh->point(TriMesh::VertexHandle(static_cast<int>(i)))[dim];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using VertexTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, VertexCloud>, VertexCloud, 3, uint32_t>;

}  // namespace

std::vector<int> PointLabels(const TriMesh& mesh, std::span<const int> face_labels,
                             std::span<const Eigen::Vector3d> points,
                             std::span<const uint8_t> is_outlier) {
  std::vector<int> labels(points.size(), -1);
  if (mesh.n_vertices() == 0) return labels;
  const VertexCloud cloud{&mesh};
  VertexTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t k) {
    if (!is_outlier.empty() && is_outlier[k]) return;
    uint32_t nearest = 0;
    double sq = 0.0;
    tree.knnSearch(points[k].data(), 1, &nearest, &sq);
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
