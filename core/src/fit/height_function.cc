// The local quadratic height function of seed 000 §2: weighted least squares
// in the frame (origin, u, w, normal) and the closest point on its graph.
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

// Smallest / largest eigenvalue ratio below which the 6x6 normal equations
// are treated as singular (points on a line, too few distinct points).
constexpr double kMinConditionRatio = 1e-10;

double Height(const std::array<double, 6>& a, double u, double w) {
  return a[0] * u * u + a[1] * w * w + a[2] * u * w + a[3] * u + a[4] * w + a[5];
}

}  // namespace

HeightFunction FitHeightFunction(std::span<const Eigen::Vector3d> points,
                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                                 std::span<const double> weights) {
  HeightFunction h;
  h.origin = origin;
  const double nn = normal.norm();
  if (!(nn > 0.0) || !std::isfinite(nn) || points.size() < 6) return h;
  h.normal = normal / nn;
  h.u_axis = fit_internal::AnyPerpendicular(h.normal);
  h.w_axis = h.normal.cross(h.u_axis);
  const bool weighted = weights.size() == points.size();

  // Scale u, w to unit RMS so the normal equations are well conditioned.
  double sum_w = 0.0;
  double sum_r2 = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double wt = weighted ? weights[i] : 1.0;
    const Eigen::Vector3d d = points[i] - origin;
    const double du = d.dot(h.u_axis);
    const double dw = d.dot(h.w_axis);
    sum_w += wt;
    sum_r2 += wt * (du * du + dw * dw);
  }
  if (!(sum_w > 0.0) || !(sum_r2 > 0.0)) return h;
  const double s = std::sqrt(sum_r2 / sum_w);

  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double wt = weighted ? weights[i] : 1.0;
    const Eigen::Vector3d d = points[i] - origin;
    const double u = d.dot(h.u_axis) / s;
    const double w = d.dot(h.w_axis) / s;
    Eigen::Matrix<double, 6, 1> phi;
    phi << u * u, w * w, u * w, u, w, 1.0;
    m.noalias() += wt * phi * phi.transpose();
    rhs.noalias() += wt * d.dot(h.normal) * phi;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(m);
  if (solver.info() != Eigen::Success) return h;
  const auto& ev = solver.eigenvalues();
  if (!(ev(0) > kMinConditionRatio * ev(5))) return h;
  const Eigen::Matrix<double, 6, 1> x =
      solver.eigenvectors() *
      (solver.eigenvalues().cwiseInverse().asDiagonal() *
       (solver.eigenvectors().transpose() * rhs));
  if (!x.allFinite()) return h;
  const double s2 = s * s;
  h.a = {x(0) / s2, x(1) / s2, x(2) / s2, x(3) / s, x(4) / s, x(5)};
  h.valid = true;
  return h;
}

Projection Project(const HeightFunction& h, const Eigen::Vector3d& p) {
  constexpr int kCorrections = 2;
  const auto& a = h.a;
  const Eigen::Vector3d d = p - h.origin;
  const Eigen::Vector3d q(d.dot(h.u_axis), d.dot(h.w_axis), d.dot(h.normal));
  double u = q.x();
  double w = q.y();
  Eigen::Vector3d foot(u, w, Height(a, u, w));
  Eigen::Vector3d n_local = Eigen::Vector3d::UnitZ();
  for (int k = 0; k <= kCorrections; ++k) {
    const double hu = 2.0 * a[0] * u + a[2] * w + a[3];
    const double hw = 2.0 * a[1] * w + a[2] * u + a[4];
    n_local = Eigen::Vector3d(-hu, -hw, 1.0).normalized();
    if (k == kCorrections) break;
    // Project p onto the tangent plane at the foot, then back onto the graph.
    const Eigen::Vector3d on_tangent = q - (q - foot).dot(n_local) * n_local;
    u = on_tangent.x();
    w = on_tangent.y();
    foot = Eigen::Vector3d(u, w, Height(a, u, w));
  }
  Projection r;
  r.point = h.origin + foot.x() * h.u_axis + foot.y() * h.w_axis + foot.z() * h.normal;
  r.normal = n_local.x() * h.u_axis + n_local.y() * h.w_axis + n_local.z() * h.normal;
  r.distance = (q - foot).dot(n_local);
  return r;
}

}  // namespace meshseg
