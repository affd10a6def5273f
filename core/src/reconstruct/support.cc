#include "reconstruct/support.h"

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {

double SpacingAtPoint(const Eigen::Vector3d& p, const mesh_internal::PointIndex& index,
                      std::vector<uint32_t>* near, std::vector<double>* dist2) {
  // p finds itself first.
  index.Nearest(p, kSpacingNeighbors + 1, near, dist2);
  double s = 0.0;
  for (size_t k = 1; k < dist2->size(); ++k) s += std::sqrt((*dist2)[k]);
  if (dist2->size() > 1) s /= static_cast<double>(dist2->size() - 1);
  return s;
}

std::vector<uint8_t> SupportedFaces(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                    const mesh_internal::PointIndex& index, double spacings,
                                    double band) {
  std::vector<uint8_t> supported(tri.n_faces(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tri.n_faces()), [&](const auto& range) {
    std::vector<uint32_t> near;
    std::vector<double> dist2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const TriMesh::FaceHandle f(static_cast<int>(i));
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const auto v : tri.fv_range(f)) centroid += ToEigen(tri.point(v));
      centroid /= 3.0;
      const Eigen::Vector3d& p = points[index.Closest(centroid)];
      const double d = (p - centroid).norm();
      supported[i] = d <= spacings * SpacingAtPoint(p, index, &near, &dist2) + band;
    }
  });
  return supported;
}

}  // namespace meshseg::reconstruct_internal
