// The torus fit's geometric residual (fit_torus.cc): the distance
// sqrt((rho - R)^2 + h^2) - r of a point to the torus with centre c, unit
// axis a, major radius R and minor radius r (h along the axis from c, rho
// the distance from the axis), with its derivatives by the tangent steps
// (centre (3), axis turned by RotateAxis (2), R, r).
#ifndef MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_
#define MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_

#include <cmath>

#include <Eigen/Core>

#include "fit/axial_lanes.h"
#include "fit/fit_internal.h"

namespace meshseg::fit_internal {

// A torus at one state, ready to evaluate residuals: (b1, b2) =
// PerpendicularBasis(axis), the basis the axis steps use.
struct TorusFrame {
  TorusFrame(const Eigen::Vector3d& center, const Eigen::Vector3d& axis, double major,
             double minor)
      : center(center), axis(axis), major(major), minor(minor) {
    PerpendicularBasis(axis, &b1, &b2);
  }
  Eigen::Vector3d center, axis, b1, b2;
  double major, minor;
};

// The residual of p and, in `row`, its derivatives by the 7 steps.
inline double TorusResidual(const TorusFrame& f, const Eigen::Vector3d& p,
                            Eigen::Matrix<double, 1, 7>* row) {
  const Eigen::Vector3d v = p - f.center;
  const double h = v.dot(f.axis);
  const Eigen::Vector3d q = v - h * f.axis;
  const double rho = q.norm();
  const Eigen::Vector3d e = rho > 0.0 ? Eigen::Vector3d(q / rho) : Eigen::Vector3d::Zero();
  const double dist = std::hypot(rho - f.major, h);
  const double gr = dist > 0.0 ? (rho - f.major) / dist : 0.0;  // d dist / d rho
  const double gh = dist > 0.0 ? h / dist : 0.0;                // d dist / d h
  row->head<3>() = -(gr * e + gh * f.axis).transpose();
  (*row)(3) = -gr * h * e.dot(f.b1) + gh * v.dot(f.b1);
  (*row)(4) = -gr * h * e.dot(f.b2) + gh * v.dot(f.b2);
  (*row)(5) = -gr;
  (*row)(6) = -1.0;
  return dist - f.minor;
}

// TorusResidual of two points at once, the same values to the bit: with
// SSE2 the two points take the two lanes of each packed operation
// (axial_lanes.h), and std::hypot is taken per lane.
inline void TorusResidualPair(const TorusFrame& f, const Eigen::Vector3d& p0,
                              const Eigen::Vector3d& p1, double* r0,
                              Eigen::Matrix<double, 1, 7>* row0, double* r1,
                              Eigen::Matrix<double, 1, 7>* row1) {
#if defined(__SSE2__)
  using namespace lanes;
  auto store = [&](__m128d x, int k) { Store(x, &(*row0)(k), &(*row1)(k)); };
  const AxialPair a(f.center, f.axis, p0, p1);
  const __m128d off = _mm_sub_pd(a.rho, Both(f.major));  // rho - R
  double off0, off1, h0, h1;
  Store(off, &off0, &off1);
  Store(a.h, &h0, &h1);
  const __m128d dist = _mm_set_pd(std::hypot(off1, h1), std::hypot(off0, h0));
  const __m128d dist_positive = _mm_cmpgt_pd(dist, _mm_setzero_pd());
  const __m128d gr = _mm_and_pd(dist_positive, _mm_div_pd(off, dist));
  const __m128d gh = _mm_and_pd(dist_positive, _mm_div_pd(a.h, dist));
  store(Negated(_mm_add_pd(_mm_mul_pd(gr, a.ex), _mm_mul_pd(gh, Both(f.axis.x())))), 0);
  store(Negated(_mm_add_pd(_mm_mul_pd(gr, a.ey), _mm_mul_pd(gh, Both(f.axis.y())))), 1);
  store(Negated(_mm_add_pd(_mm_mul_pd(gr, a.ez), _mm_mul_pd(gh, Both(f.axis.z())))), 2);
  const __m128d grh = _mm_mul_pd(Negated(gr), a.h);  // -gr h
  store(_mm_add_pd(_mm_mul_pd(grh, Dot(a.ex, a.ey, a.ez, f.b1)),
                   _mm_mul_pd(gh, Dot(a.vx, a.vy, a.vz, f.b1))),
        3);
  store(_mm_add_pd(_mm_mul_pd(grh, Dot(a.ex, a.ey, a.ez, f.b2)),
                   _mm_mul_pd(gh, Dot(a.vx, a.vy, a.vz, f.b2))),
        4);
  store(Negated(gr), 5);
  store(Both(-1.0), 6);
  Store(_mm_sub_pd(dist, Both(f.minor)), r0, r1);
#else
  *r0 = TorusResidual(f, p0, row0);
  *r1 = TorusResidual(f, p1, row1);
#endif
}

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_
