#include "curvature/local_fit.h"

#include <cmath>

namespace meshseg::curvature_internal {

LocalFit FitAtVertex(std::span<const Eigen::Vector3d> positions, std::span<const double> area,
                     std::span<const int> neighborhood, const Eigen::Vector3d& normal,
                     std::vector<Eigen::Vector3d>* local, std::vector<double>* weights) {
  LocalFit r;
  if (neighborhood.size() < 6) return r;
  const Eigen::Vector3d& origin = positions[neighborhood.front()];
  HeightFunction h;
  if (!HeightFrame(origin, normal, &h)) return r;
  // Each neighbour once in the frame: the fit and its residuals both read
  // these coordinates.
  local->clear();
  weights->clear();
  for (const int j : neighborhood) {
    const Eigen::Vector3d d = positions[j] - origin;
    local->emplace_back(d.dot(h.u_axis), d.dot(h.w_axis), d.dot(h.normal));
    // Area weights keep long thin CAD triangles from dominating (a floor
    // keeps zero-area vertices in the fit).
    weights->push_back(area[j] + 1e-12);
  }
  FitHeightInFrame(*local, *weights, &h);
  if (!h.valid) return r;
  const auto& a = h.a;
  double sum_w = 0.0;
  double sum_r2 = 0.0;
  for (std::size_t k = 0; k < local->size(); ++k) {
    const double u = (*local)[k].x();
    const double w = (*local)[k].y();
    const double res = (*local)[k].z() -
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
