// Cylinder fit, seed 002 then seed 000 §5: the axis is the normal of the
// plane through the origin fitted to the normals on the Gauss sphere (the
// smallest eigenvector of Σ w n nᵀ), an algebraic circle fit of the points
// projected along it gives the axis point and radius, and Levenberg–Marquardt
// refines the geometric distance (on a narrow arc the second eigenvector and
// the points' longest direction are tried as the axis too). Without normals
// each principal axis of the points is tried as the initial axis and the
// best refined fit is kept.
#include <cmath>
#include <vector>

#include "fit/axial_fit.h"
#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

// Eigenvalue ratios below which the input is degenerate.
constexpr double kCollinearRatio = 1e-12;       // point scatter: points on a line
constexpr double kParallelNormalsRatio = 1e-10;  // normal scatter: one normal direction
// Normal scatter across the fan below this share of the largest: an arc of
// under about 60 degrees.
constexpr double kNarrowFanRatio = 0.25;

}  // namespace

FitResult FitCylinder(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  if (input.points.size() < 5) return InvalidResult(Cylinder{});
  const Moments m = PointMoments(input);
  if (!(m.weight_sum > 0.0)) return InvalidResult(Cylinder{});
  const Eigen3 pca = SymmetricEigen(m.scatter);
  if (!(pca.values(1) > kCollinearRatio * pca.values(2))) return InvalidResult(Cylinder{});

  std::vector<Eigen::Vector3d> axes;
  if (HasNormals(input)) {
    const Eigen3 e = SymmetricEigen(NormalMoment(input));
    if (!(e.values(1) > kParallelNormalsRatio * e.values(2))) return InvalidResult(Cylinder{});
    axes.push_back(e.vectors.col(0));
    // On a narrow arc the normals fan out little across it, and noisy or
    // smoothed normals can make the fan's own direction look flatter than
    // the axis (a 30-degree band of a radius-4 round at 0.15 h converged to
    // r 2077 across the true axis); the fan direction is tried as well, and
    // the points' longest direction, for normals scattered aslant, where
    // both of the Gauss sphere's are well off the axis (22 and 68 degrees on
    // a quarter-round edge band of a prism at 0.15 h, which fitted r 469).
    if (e.values(1) < kNarrowFanRatio * e.values(2)) {
      axes.push_back(e.vectors.col(1));
      axes.push_back(pca.vectors.col(2));
    }
  } else {
    if (!(pca.values(0) > kCollinearRatio * pca.values(2))) return InvalidResult(Cylinder{});
    for (int k = 0; k < 3; ++k) axes.push_back(pca.vectors.col(k));
  }

  std::vector<AxialSurface> starts;
  for (const Eigen::Vector3d& axis : axes) {
    AxialSurface s;
    if (FitCrossSection(input, m.centroid, axis, &s)) starts.push_back(s);
  }
  FitResult r;
  AxialSurface best;
  const double best_cost =
      BestAxialFit(input, m.centroid, starts, /*fit_angle=*/false, params, &best, &r.iterations);
  const Cylinder cyl{best.origin, best.axis, std::abs(best.radius)};
  if (!std::isfinite(best_cost) || !cyl.axis_origin.allFinite() || !cyl.axis_direction.allFinite() ||
      !std::isfinite(cyl.radius) || !(cyl.radius > 0.0)) {
    return InvalidResult(Cylinder{});
  }
  r.surface = cyl;
  r.valid = true;
  SetDistanceErrors(input, &r);
  return r;
}

}  // namespace meshseg
