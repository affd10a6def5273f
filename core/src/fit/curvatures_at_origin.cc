// Principal curvatures of the graph of a height function at (u, w) = (0, 0)
// from its first and second fundamental forms (seed 000 §2), including the
// slope terms a3, a4.
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include "meshseg/fit.h"

namespace meshseg {

PrincipalCurvatures CurvaturesAtOrigin(const HeightFunction& h) {
  const auto& a = h.a;
  // X(u, w) = origin + u U + w W + h(u, w) N; derivatives at the origin.
  const double hu = a[3];
  const double hw = a[4];
  const double huu = 2.0 * a[0];
  const double hww = 2.0 * a[1];
  const double huw = a[2];
  const double len = std::sqrt(1.0 + hu * hu + hw * hw);
  Eigen::Matrix2d first;
  first << 1.0 + hu * hu, hu * hw, hu * hw, 1.0 + hw * hw;
  Eigen::Matrix2d second;
  second << huu, huw, huw, hww;
  second /= len;

  // Shape operator eigenproblem II v = κ I v (I is positive definite).
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(second, first);
  PrincipalCurvatures pc;
  pc.normal = (h.normal - hu * h.u_axis - hw * h.w_axis) / len;
  if (solver.info() != Eigen::Success) return pc;
  const Eigen::Vector2d k = solver.eigenvalues();
  const Eigen::Matrix2d v = solver.eigenvectors();
  const Eigen::Vector3d xu = h.u_axis + hu * h.normal;
  const Eigen::Vector3d xw = h.w_axis + hw * h.normal;
  int i_max = std::abs(k(1)) >= std::abs(k(0)) ? 1 : 0;
  int i_min = 1 - i_max;
  pc.kappa_max = k(i_max);
  pc.kappa_min = k(i_min);
  pc.dir_max = (v(0, i_max) * xu + v(1, i_max) * xw).normalized();
  pc.dir_min = (v(0, i_min) * xu + v(1, i_min) * xw).normalized();
  return pc;
}

}  // namespace meshseg
