#include "fit/fit_internal.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace meshseg::fit_internal {

Moments PointMoments(const FitInput& input) {
  Moments m;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const double w = WeightAt(input, i);
    m.centroid += w * input.points[i];
    m.weight_sum += w;
  }
  if (m.weight_sum <= 0.0) return Moments{};
  m.centroid /= m.weight_sum;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d d = input.points[i] - m.centroid;
    m.scatter.noalias() += WeightAt(input, i) * d * d.transpose();
  }
  return m;
}

Eigen::Matrix3d NormalMoment(const FitInput& input) {
  Eigen::Matrix3d gauss = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < input.normals.size(); ++i) {
    gauss.noalias() += WeightAt(input, i) * input.normals[i] * input.normals[i].transpose();
  }
  return gauss;
}

Eigen3 SymmetricEigen(const Eigen::Matrix3d& m) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  Eigen3 e;
  if (solver.info() != Eigen::Success) return e;
  e.values = solver.eigenvalues();
  e.vectors = solver.eigenvectors();
  return e;
}

Eigen::Vector3d AnyPerpendicular(const Eigen::Vector3d& a) {
  // Cross with the coordinate axis least aligned with a: well conditioned.
  int k = 0;
  a.cwiseAbs().minCoeff(&k);
  const Eigen::Vector3d p = a.cross(Eigen::Vector3d::Unit(k));
  const double n = p.norm();
  return n > 0.0 ? Eigen::Vector3d(p / n) : Eigen::Vector3d::UnitX();
}

void PerpendicularBasis(const Eigen::Vector3d& a, Eigen::Vector3d* b1, Eigen::Vector3d* b2) {
  *b1 = AnyPerpendicular(a);
  *b2 = a.cross(*b1).normalized();
}

Eigen::Vector3d RotateAxis(const Eigen::Vector3d& a, double t1, double t2) {
  Eigen::Vector3d b1, b2;
  PerpendicularBasis(a, &b1, &b2);
  return RotateAxis(a, b1, b2, t1, t2);
}

Eigen::Vector3d RotateAxis(const Eigen::Vector3d& a, const Eigen::Vector3d& b1,
                           const Eigen::Vector3d& b2, double t1, double t2) {
  const Eigen::Vector3d r = a + t1 * b1 + t2 * b2;
  return r.normalized();
}

void SetDistanceErrors(const FitInput& input, FitResult* result) {
  const bool with_normals = HasNormals(input);
  double sum_sq = 0.0;
  double max_abs = 0.0;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d hint = with_normals ? input.normals[i] : Eigen::Vector3d::Zero();
    const double d = std::abs(Project(result->surface, input.points[i], hint).distance);
    sum_sq += d * d;
    max_abs = std::max(max_abs, d);
  }
  const std::size_t n = input.points.size();
  result->rms_distance = n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  result->max_distance = max_abs;
}

FitResult InvalidResult(const Surface& surface) {
  FitResult r;
  r.surface = surface;
  r.valid = false;
  return r;
}

}  // namespace meshseg::fit_internal
