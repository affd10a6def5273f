#include "fit/project_quadric.h"

#include <cmath>
#include <limits>

namespace meshseg::fit_internal {
namespace {

// The symmetric matrix A with f(x) = x^T A x + b . x + c.
Eigen::Matrix3d QuadraticPart(const Quadric& q) {
  const auto& c = q.c;
  Eigen::Matrix3d a;
  a << c[0], 0.5 * c[3], 0.5 * c[5],
       0.5 * c[3], c[1], 0.5 * c[4],
       0.5 * c[5], 0.5 * c[4], c[2];
  return a;
}

// Root of smallest |t| of a t² + b t + c = 0 (numerically stable form), or
// NaN if there is no real root.
double SmallestRoot(double a, double b, double c) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return nan;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) return c == 0.0 ? 0.0 : nan;
  const double t_small = c / q;
  const double t_large = a != 0.0 ? q / a : std::numeric_limits<double>::infinity();
  double best = nan;
  for (const double t : {t_small, t_large}) {
    if (std::isfinite(t) && !(std::abs(t) >= std::abs(best))) best = t;
  }
  return best;
}

}  // namespace

double QuadricValue(const Quadric& q, const Eigen::Vector3d& x) {
  const auto& c = q.c;
  return c[0] * x.x() * x.x() + c[1] * x.y() * x.y() + c[2] * x.z() * x.z() +
         c[3] * x.x() * x.y() + c[4] * x.y() * x.z() + c[5] * x.z() * x.x() +
         c[6] * x.x() + c[7] * x.y() + c[8] * x.z() + c[9];
}

Eigen::Vector3d QuadricGradient(const Quadric& q, const Eigen::Vector3d& x) {
  const auto& c = q.c;
  return {2.0 * c[0] * x.x() + c[3] * x.y() + c[5] * x.z() + c[6],
          2.0 * c[1] * x.y() + c[3] * x.x() + c[4] * x.z() + c[7],
          2.0 * c[2] * x.z() + c[4] * x.y() + c[5] * x.x() + c[8]};
}

Projection ProjectQuadric(const Quadric& q, const Eigen::Vector3d& p,
                          const Eigen::Vector3d& hint) {
  constexpr int kSteps = 3;  // seed 000 §5: three iterations suffice
  const Eigen::Matrix3d a = QuadraticPart(q);
  const double f_p = QuadricValue(q, p);
  const Eigen::Vector3d grad_p = QuadricGradient(q, p);
  Eigen::Vector3d d = hint.squaredNorm() > 0.0 ? hint : grad_p;
  if (!(d.squaredNorm() > 0.0) || !d.allFinite()) d = Eigen::Vector3d::UnitZ();
  d.normalize();
  Eigen::Vector3d foot = p;
  for (int k = 0; k < kSteps; ++k) {
    // f(p + t d) = (d^T A d) t² + (∇f(p) . d) t + f(p).
    const double t = SmallestRoot(d.dot(a * d), grad_p.dot(d), f_p);
    if (std::isfinite(t)) {
      foot = p + t * d;
    } else {
      const Eigen::Vector3d g = QuadricGradient(q, foot);
      const double g2 = g.squaredNorm();
      if (g2 > 0.0) foot -= (QuadricValue(q, foot) / g2) * g;
    }
    const Eigen::Vector3d g = QuadricGradient(q, foot);
    const double gn = g.norm();
    if (!(gn > 0.0) || !std::isfinite(gn)) break;
    d = g / gn;
  }
  const Eigen::Vector3d g = QuadricGradient(q, foot);
  const double gn = g.norm();
  const Eigen::Vector3d normal = (gn > 0.0 && std::isfinite(gn)) ? Eigen::Vector3d(g / gn) : d;
  return {foot, normal, (p - foot).dot(normal)};
}

}  // namespace meshseg::fit_internal
