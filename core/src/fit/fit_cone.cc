// Cone fit, seed 002 then seed 000 §5. Initial values from the normals: the
// axis d is the normal of the plane fitted to the normals on the Gauss sphere
// (they lie on a small circle around d), the apex a solves
// Σ w n nᵀ a = Σ w n (n · v) (every normal line meets the axis at the apex),
// the half angle is the mean of asin(d · n); the cylinder's start (angle 0)
// is tried too. Without usable normals the axis line comes from a circle fit
// as for the cylinder, with angle 0. Then Levenberg–Marquardt on the
// distance to the generator line.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <Eigen/Cholesky>

#include "fit/axial_fit.h"
#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

using fit_internal::AxialSurface;

constexpr double kCollinearRatio = 1e-12;
constexpr double kParallelNormalsRatio = 1e-10;
constexpr double kApexConditionRatio = 1e-9;  // Σ n nᵀ: below, the apex is ill-posed
constexpr double kMinTanAngle = 1e-12;        // below, the "cone" is a cylinder

// Seed 002 initial cone from normals (`gauss` = NormalMoment(input)); false
// if the normals do not define one.
bool InitialConeFromNormals(const FitInput& input, const fit_internal::Moments& m,
                            const Eigen::Matrix3d& gauss, AxialSurface* s) {
  using namespace fit_internal;
  Eigen::Vector3d mean_n = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < input.normals.size(); ++i) mean_n += WeightAt(input, i) * input.normals[i];
  mean_n /= m.weight_sum;
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < input.normals.size(); ++i) {
    const double w = WeightAt(input, i);
    const Eigen::Vector3d& n = input.normals[i];
    spread.noalias() += w * (n - mean_n) * (n - mean_n).transpose();
    rhs += w * n * n.dot(input.points[i] - m.centroid);
  }
  const Eigen3 e = SymmetricEigen(spread);
  if (!(e.values(1) > kParallelNormalsRatio * m.weight_sum)) return false;
  Eigen::Vector3d d = e.vectors.col(0);
  const Eigen3 g = SymmetricEigen(gauss);
  if (!(g.values(0) > kApexConditionRatio * g.values(2))) {
    return FitCrossSection(input, m.centroid, d, s);
  }
  const Eigen::Vector3d apex = m.centroid + gauss.ldlt().solve(rhs);
  if (d.dot(m.centroid - apex) < 0.0) d = -d;  // apex -> opening
  double mean_asin = 0.0;
  for (std::size_t i = 0; i < input.normals.size(); ++i) {
    mean_asin += WeightAt(input, i) * std::asin(std::clamp(d.dot(input.normals[i]), -1.0, 1.0));
  }
  const double angle = std::abs(mean_asin / m.weight_sum);
  s->axis = d;
  s->origin = apex + (m.centroid - apex).dot(d) * d;
  s->angle = angle;
  double radius = 0.0;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d v = input.points[i] - s->origin;
    const double h = v.dot(d);
    radius += WeightAt(input, i) * ((v - h * d).norm() - h * std::tan(angle));
  }
  s->radius = radius / m.weight_sum;
  return s->origin.allFinite() && std::isfinite(s->radius);
}

}  // namespace

FitResult FitCone(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  if (input.points.size() < 6) return InvalidResult(Cone{});
  const Moments m = PointMoments(input);
  if (!(m.weight_sum > 0.0)) return InvalidResult(Cone{});
  const Eigen3 pca = SymmetricEigen(m.scatter);
  if (!(pca.values(1) > kCollinearRatio * pca.values(2))) return InvalidResult(Cone{});

  std::vector<AxialSurface> starts;
  if (HasNormals(input)) {
    const Eigen::Matrix3d gauss = NormalMoment(input);
    AxialSurface s;
    if (!InitialConeFromNormals(input, m, gauss, &s)) return InvalidResult(Cone{});
    starts.push_back(s);
    // The cylinder's start (seed 002) as well: angle 0 about the smallest
    // eigenvector of Σ w n nᵀ. The apex solve trusts every normal; where
    // smoothed normals turn toward the faces beyond a region's creases (a
    // groove's rims and ends) it can put the axis far off: on a narrow
    // cylindrical groove at 0.15 h the normals gave 52 degrees, and LM went
    // on to a cone of 87 degrees, rms 2.1 against a noise of 0.15.
    AxialSurface cylinder;
    if (FitCrossSection(input, m.centroid, SymmetricEigen(gauss).vectors.col(0), &cylinder)) {
      starts.push_back(cylinder);
    }
  } else {
    if (!(pca.values(0) > kCollinearRatio * pca.values(2))) return InvalidResult(Cone{});
    for (int k = 0; k < 3; ++k) {
      AxialSurface s;
      if (FitCrossSection(input, m.centroid, pca.vectors.col(k), &s)) starts.push_back(s);
    }
  }

  FitResult r;
  AxialSurface best;
  const double best_cost =
      BestAxialFit(input, m.centroid, starts, /*fit_angle=*/true, params, &best, &r.iterations);
  // rho = radius + h tan(angle): the apex is where rho = 0.
  double t = std::tan(best.angle);
  Eigen::Vector3d axis = best.axis;
  if (t < 0.0) {
    t = -t;
    axis = -axis;
  }
  if (!std::isfinite(best_cost) || !std::isfinite(t) || !(t > kMinTanAngle)) {
    return InvalidResult(Cone{});
  }
  const Cone cone{best.origin - (best.radius / t) * axis, axis, std::atan(t)};
  if (!cone.apex.allFinite() || !cone.axis_direction.allFinite()) return InvalidResult(Cone{});
  r.surface = cone;
  r.valid = true;
  SetDistanceErrors(input, &r);
  return r;
}

double ConeWidening(const Cone& cone, std::span<const Eigen::Vector3d> points) {
  if (points.empty()) return 0.0;
  const Eigen::Vector3d axis = cone.axis_direction.normalized();
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    const double t = (p - cone.apex).dot(axis);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  return (hi - lo) * std::tan(cone.half_angle);
}

}  // namespace meshseg
