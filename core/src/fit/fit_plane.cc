// Plane fit: seed 002's fast fit from the mean smoothed normal, or (refine)
// the orthogonal least-squares plane, i.e. the smallest principal axis of the
// weighted scatter, which is the exact geometric optimum.
#include <cmath>

#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

// Second-smallest / largest scatter eigenvalue below which the points are
// collinear and span no plane.
constexpr double kCollinearRatio = 1e-12;

}  // namespace

FitResult FitPlane(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  Plane plane;
  if (input.points.size() < 3) return InvalidResult(plane);
  const Moments m = PointMoments(input);
  if (!(m.weight_sum > 0.0)) return InvalidResult(plane);
  plane.point = m.centroid;

  Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero();
  if (HasNormals(input)) {
    for (std::size_t i = 0; i < input.normals.size(); ++i) {
      mean_normal += WeightAt(input, i) * input.normals[i];
    }
  }
  const Eigen3 e = SymmetricEigen(m.scatter);
  const bool spans_plane = e.values(1) > kCollinearRatio * e.values(2);
  const bool has_mean_normal = mean_normal.norm() > 1e-12 * m.weight_sum;

  if (!params.refine && has_mean_normal) {
    plane.normal = mean_normal.normalized();  // seed 002 fast linear fit
  } else if (spans_plane) {
    plane.normal = e.vectors.col(0);
    if (has_mean_normal && plane.normal.dot(mean_normal) < 0.0) plane.normal = -plane.normal;
  } else {
    return InvalidResult(plane);
  }
  if (!plane.normal.allFinite() || !plane.point.allFinite()) return InvalidResult(Plane{});
  FitResult r;
  r.surface = plane;
  r.valid = true;
  SetDistanceErrors(input, &r);
  return r;
}

}  // namespace meshseg
