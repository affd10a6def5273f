// The torus fit's geometric residual (fit_torus.cc): the distance
// sqrt((rho - R)^2 + h^2) - r of a point to the torus with centre c, unit
// axis a, major radius R and minor radius r (h along the axis from c, rho
// the distance from the axis), with its derivatives by the tangent steps
// (centre (3), axis turned by RotateAxis (2), R, r).
#ifndef MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_
#define MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_

#include <cmath>

#include <Eigen/Core>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
// SSE2 the two points take the two lanes of each packed operation, every
// lane in the scalar formula's order (Eigen sums a Vector3d's products as
// (x0 + x1) + x2; packed IEEE operations round each lane as scalar ones
// do), and std::hypot is taken per lane.
inline void TorusResidualPair(const TorusFrame& f, const Eigen::Vector3d& p0,
                              const Eigen::Vector3d& p1, double* r0,
                              Eigen::Matrix<double, 1, 7>* row0, double* r1,
                              Eigen::Matrix<double, 1, 7>* row1) {
#if defined(__SSE2__)
  auto both = [](double x) { return _mm_set1_pd(x); };
  auto dot = [](__m128d x0, __m128d x1, __m128d x2, __m128d y0, __m128d y1, __m128d y2) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, y0), _mm_mul_pd(x1, y1)), _mm_mul_pd(x2, y2));
  };
  auto neg = [](__m128d x) { return _mm_xor_pd(x, _mm_set1_pd(-0.0)); };
  auto store = [&](__m128d x, int k) {
    alignas(16) double lanes[2];
    _mm_store_pd(lanes, x);
    (*row0)(k) = lanes[0];
    (*row1)(k) = lanes[1];
  };
  const __m128d ax = both(f.axis.x()), ay = both(f.axis.y()), az = both(f.axis.z());
  const __m128d vx = _mm_sub_pd(_mm_set_pd(p1.x(), p0.x()), both(f.center.x()));
  const __m128d vy = _mm_sub_pd(_mm_set_pd(p1.y(), p0.y()), both(f.center.y()));
  const __m128d vz = _mm_sub_pd(_mm_set_pd(p1.z(), p0.z()), both(f.center.z()));
  const __m128d h = dot(vx, vy, vz, ax, ay, az);
  const __m128d qx = _mm_sub_pd(vx, _mm_mul_pd(h, ax));
  const __m128d qy = _mm_sub_pd(vy, _mm_mul_pd(h, ay));
  const __m128d qz = _mm_sub_pd(vz, _mm_mul_pd(h, az));
  const __m128d rho = _mm_sqrt_pd(dot(qx, qy, qz, qx, qy, qz));
  const __m128d rho_positive = _mm_cmpgt_pd(rho, _mm_setzero_pd());
  const __m128d ex = _mm_and_pd(rho_positive, _mm_div_pd(qx, rho));
  const __m128d ey = _mm_and_pd(rho_positive, _mm_div_pd(qy, rho));
  const __m128d ez = _mm_and_pd(rho_positive, _mm_div_pd(qz, rho));
  const __m128d off = _mm_sub_pd(rho, both(f.major));  // rho - R
  alignas(16) double off_lanes[2], h_lanes[2];
  _mm_store_pd(off_lanes, off);
  _mm_store_pd(h_lanes, h);
  const __m128d dist = _mm_set_pd(std::hypot(off_lanes[1], h_lanes[1]),
                                  std::hypot(off_lanes[0], h_lanes[0]));
  const __m128d dist_positive = _mm_cmpgt_pd(dist, _mm_setzero_pd());
  const __m128d gr = _mm_and_pd(dist_positive, _mm_div_pd(off, dist));
  const __m128d gh = _mm_and_pd(dist_positive, _mm_div_pd(h, dist));
  store(neg(_mm_add_pd(_mm_mul_pd(gr, ex), _mm_mul_pd(gh, ax))), 0);
  store(neg(_mm_add_pd(_mm_mul_pd(gr, ey), _mm_mul_pd(gh, ay))), 1);
  store(neg(_mm_add_pd(_mm_mul_pd(gr, ez), _mm_mul_pd(gh, az))), 2);
  const __m128d grh = _mm_mul_pd(neg(gr), h);  // -gr h
  const __m128d b1x = both(f.b1.x()), b1y = both(f.b1.y()), b1z = both(f.b1.z());
  const __m128d b2x = both(f.b2.x()), b2y = both(f.b2.y()), b2z = both(f.b2.z());
  store(_mm_add_pd(_mm_mul_pd(grh, dot(ex, ey, ez, b1x, b1y, b1z)),
                   _mm_mul_pd(gh, dot(vx, vy, vz, b1x, b1y, b1z))),
        3);
  store(_mm_add_pd(_mm_mul_pd(grh, dot(ex, ey, ez, b2x, b2y, b2z)),
                   _mm_mul_pd(gh, dot(vx, vy, vz, b2x, b2y, b2z))),
        4);
  store(neg(gr), 5);
  store(both(-1.0), 6);
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, _mm_sub_pd(dist, both(f.minor)));
  *r0 = lanes[0];
  *r1 = lanes[1];
#else
  *r0 = TorusResidual(f, p0, row0);
  *r1 = TorusResidual(f, p1, row1);
#endif
}

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_TORUS_RESIDUAL_H_
