#include "pipeline/point_labels.h"

#include <algorithm>
#include <limits>

#include <nanoflann.hpp>
#include <tbb/parallel_for.h>

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

// Squared distance from p to triangle abc (Ericson, Real-Time Collision
// Detection §5.1.5: closest point by Voronoi regions).
double SquaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (ap - ab * (d1 / (d1 - d3))).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (ap - ac * (d2 / (d2 - d6))).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return (bp - (c - b) * w).squaredNorm();
  }
  const double denom = 1.0 / (va + vb + vc);
  const Eigen::Vector3d q = a + ab * (vb * denom) + ac * (vc * denom);
  return (p - q).squaredNorm();
}

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
