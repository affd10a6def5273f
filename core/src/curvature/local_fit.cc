#include "curvature/local_fit.h"

#include <cmath>

namespace meshseg::curvature_internal {

LocalFit FitAtVertex(std::span<const Eigen::Vector3d> positions, std::span<const double> area,
                     std::span<const int> neighborhood, const Eigen::Vector3d& normal,
                     std::vector<Eigen::Vector3d>* points, std::vector<double>* weights) {
  LocalFit r;
  if (neighborhood.size() < 6) return r;
  points->clear();
  weights->clear();
  for (const int j : neighborhood) {
    points->push_back(positions[j]);
    // Area weights keep long thin CAD triangles from dominating (a floor
    // keeps zero-area vertices in the fit).
    weights->push_back(area[j] + 1e-12);
  }
  const Eigen::Vector3d& origin = positions[neighborhood.front()];
  const HeightFunction h = FitHeightFunction(*points, origin, normal, *weights);
  if (!h.valid) return r;
  const auto& a = h.a;
  double sum_w = 0.0;
  double sum_r2 = 0.0;
  for (std::size_t k = 0; k < points->size(); ++k) {
    const Eigen::Vector3d d = (*points)[k] - origin;
    const double u = d.dot(h.u_axis);
    const double w = d.dot(h.w_axis);
    const double res = d.dot(h.normal) -
                       (a[0] * u * u + a[1] * w * w + a[2] * u * w + a[3] * u + a[4] * w + a[5]);
    sum_w += (*weights)[k];
    sum_r2 += (*weights)[k] * res * res;
  }
  r.curvatures = CurvaturesAtOrigin(h);
  r.residual = sum_w > 0.0 ? std::sqrt(sum_r2 / sum_w) : 0.0;
  r.valid = std::isfinite(r.curvatures.kappa_max) && std::isfinite(r.curvatures.kappa_min);
  return r;
}

}  // namespace meshseg::curvature_internal
