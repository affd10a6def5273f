// Algebraic (Kåsa) circle / sphere fit in D dimensions: minimises
// Σ w (|x|² + b . x + c)², a linear problem, on centred and scaled points.
// Seed 002 uses it for the sphere and, in 2D, for the cylinder's and torus's
// cross-sections. Biased towards small radii on short arcs; the geometric
// refinement removes that.
#ifndef MESHSEG_SRC_FIT_ALGEBRAIC_SPHERE_H_
#define MESHSEG_SRC_FIT_ALGEBRAIC_SPHERE_H_

#include <cmath>
#include <cstddef>
#include <span>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace meshseg::fit_internal {

template <int D>
struct AlgebraicSphere {
  Eigen::Matrix<double, D, 1> center = Eigen::Matrix<double, D, 1>::Zero();
  double radius = 0.0;
  bool valid = false;  // false: too few points, or all on a line / plane
};

// `weights` empty = all 1.
template <int D>
AlgebraicSphere<D> FitAlgebraicSphere(std::span<const Eigen::Matrix<double, D, 1>> points,
                                      std::span<const double> weights) {
  using Vec = Eigen::Matrix<double, D, 1>;
  using Phi = Eigen::Matrix<double, D + 1, 1>;
  constexpr double kMinConditionRatio = 1e-12;
  AlgebraicSphere<D> out;
  if (points.size() < static_cast<std::size_t>(D + 1)) return out;
  const auto weight = [&](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  Vec c = Vec::Zero();
  double sum_w = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    c += weight(i) * points[i];
    sum_w += weight(i);
  }
  if (!(sum_w > 0.0)) return out;
  c /= sum_w;
  double sum_r2 = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) sum_r2 += weight(i) * (points[i] - c).squaredNorm();
  if (!(sum_r2 > 0.0)) return out;
  const double s = std::sqrt(sum_r2 / sum_w);

  Eigen::Matrix<double, D + 1, D + 1> m = Eigen::Matrix<double, D + 1, D + 1>::Zero();
  Phi rhs = Phi::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec y = (points[i] - c) / s;
    Phi phi;
    phi << y, 1.0;
    m.noalias() += weight(i) * phi * phi.transpose();
    rhs.noalias() -= (weight(i) * y.squaredNorm()) * phi;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D + 1, D + 1>> solver(m);
  if (solver.info() != Eigen::Success) return out;
  const auto& ev = solver.eigenvalues();
  if (!(ev(0) > kMinConditionRatio * ev(D))) return out;
  const Phi sol = solver.eigenvectors() *
                  (ev.cwiseInverse().asDiagonal() * (solver.eigenvectors().transpose() * rhs));
  const Vec center_y = -0.5 * sol.template head<D>();
  const double r2 = center_y.squaredNorm() - sol(D);
  if (!(r2 > 0.0) || !sol.allFinite()) return out;
  out.center = c + s * center_y;
  out.radius = s * std::sqrt(r2);
  out.valid = true;
  return out;
}

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_ALGEBRAIC_SPHERE_H_
