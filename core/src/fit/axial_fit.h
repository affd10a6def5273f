// Shared by the cylinder and cone fits: surfaces whose generator, in the
// half-plane through the axis, is the line rho = radius + h tan(angle)
// (h along the axis from `origin`, rho the distance from the axis). The
// cylinder is angle = 0. Geometric residual (signed distance to the
// generator line): r = (rho - radius) cos(angle) - h sin(angle).
#ifndef MESHSEG_SRC_FIT_AXIAL_FIT_H_
#define MESHSEG_SRC_FIT_AXIAL_FIT_H_

#include <span>

#include <Eigen/Core>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "fit/levenberg_marquardt.h"
#include "meshseg/fit.h"

namespace meshseg::fit_internal {

struct AxialSurface {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // on the axis
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // unit
  double radius = 0.0;                               // rho at origin
  double angle = 0.0;                                // radians, signed
};

// An axial surface at one state, ready to evaluate residuals: (b1, b2) =
// PerpendicularBasis(axis), the basis the tangent steps use.
struct AxialFrame {
  AxialFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double radius,
             double angle);
  Eigen::Vector3d origin, axis, b1, b2;
  double radius, cos_angle, sin_angle;
};

// The residual of p (signed distance to the generator line) and, in `row`,
// its derivatives by the tangent steps (s1, s2, t1, t2, radius[, angle]): the
// origin moved by s1 b1 + s2 b2, the axis turned by RotateAxis(axis, t1, t2).
// P = 5 leaves out the angle.
template <int P>
double AxialResidual(const AxialFrame& f, const Eigen::Vector3d& p,
                     Eigen::Matrix<double, 1, P>* row) {
  static_assert(P == 5 || P == 6);
  const Eigen::Vector3d v = p - f.origin;
  const double h = v.dot(f.axis);
  const Eigen::Vector3d q = v - h * f.axis;
  const double rho = q.norm();
  const Eigen::Vector3d e = rho > 0.0 ? Eigen::Vector3d(q / rho) : Eigen::Vector3d::Zero();
  const double eb1 = e.dot(f.b1), eb2 = e.dot(f.b2);
  if (P == 5 && f.sin_angle == 0.0 && f.cos_angle == 1.0) {
    // A cylinder (angle 0): the general formulas below with their products
    // by cos = 1 (exact) and their terms times sin = 0 left out. A term
    // 0 * x changes no value but, at most, the sign of a zero; in the
    // normal equations a zero adds nothing to a sum, and no sum is ever -0
    // (they start at +0, and x + (-x) rounds to +0), so J^T W J and J^T W r
    // are the same to the bit.
    (*row)(0) = -eb1;
    (*row)(1) = -eb2;
    (*row)(2) = -h * eb1;
    (*row)(3) = -h * eb2;
    (*row)(4) = -1.0;
    return rho - f.radius;
  }
  (*row)(0) = -f.cos_angle * eb1;
  (*row)(1) = -f.cos_angle * eb2;
  (*row)(2) = -h * f.cos_angle * eb1 - f.sin_angle * v.dot(f.b1);
  (*row)(3) = -h * f.cos_angle * eb2 - f.sin_angle * v.dot(f.b2);
  (*row)(4) = -f.cos_angle;
  if constexpr (P == 6) (*row)(5) = -(rho - f.radius) * f.sin_angle - h * f.cos_angle;
  return (rho - f.radius) * f.cos_angle - h * f.sin_angle;
}

// AxialResidual of two points at once, p0 into (*r0, row0) and p1 into
// (*r1, row1): the same values to the bit. With SSE2 the two points take
// the two lanes of each packed operation; every lane runs the scalar
// formula's operations in its order (Eigen sums a Vector3d's products as
// (x0 + x1) + x2), and packed IEEE arithmetic rounds each lane as scalar
// arithmetic does, so only the count of instructions changes (the
// divisions and square roots, most of a residual's time, are shared).
template <int P>
void AxialResidualPair(const AxialFrame& f, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                       double* r0, Eigen::Matrix<double, 1, P>* row0, double* r1,
                       Eigen::Matrix<double, 1, P>* row1) {
  static_assert(P == 5 || P == 6);
#if defined(__SSE2__)
  auto both = [](double x) { return _mm_set1_pd(x); };
  // (x0 y0 + x1 y1) + x2 y2 per lane, as Eigen's dot of two Vector3d.
  auto dot = [](__m128d x0, __m128d x1, __m128d x2, __m128d y0, __m128d y1, __m128d y2) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, y0), _mm_mul_pd(x1, y1)), _mm_mul_pd(x2, y2));
  };
  auto store = [&](__m128d x, int k) {
    alignas(16) double lanes[2];
    _mm_store_pd(lanes, x);
    (*row0)(k) = lanes[0];
    (*row1)(k) = lanes[1];
  };
  auto neg = [](__m128d x) { return _mm_xor_pd(x, _mm_set1_pd(-0.0)); };
  const __m128d ax = both(f.axis.x()), ay = both(f.axis.y()), az = both(f.axis.z());
  const __m128d vx = _mm_sub_pd(_mm_set_pd(p1.x(), p0.x()), both(f.origin.x()));
  const __m128d vy = _mm_sub_pd(_mm_set_pd(p1.y(), p0.y()), both(f.origin.y()));
  const __m128d vz = _mm_sub_pd(_mm_set_pd(p1.z(), p0.z()), both(f.origin.z()));
  const __m128d h = dot(vx, vy, vz, ax, ay, az);
  const __m128d qx = _mm_sub_pd(vx, _mm_mul_pd(h, ax));
  const __m128d qy = _mm_sub_pd(vy, _mm_mul_pd(h, ay));
  const __m128d qz = _mm_sub_pd(vz, _mm_mul_pd(h, az));
  const __m128d rho = _mm_sqrt_pd(dot(qx, qy, qz, qx, qy, qz));
  // e = q / rho where rho > 0, else 0 (the lane's 0 / 0 is masked off).
  const __m128d positive = _mm_cmpgt_pd(rho, _mm_setzero_pd());
  const __m128d ex = _mm_and_pd(positive, _mm_div_pd(qx, rho));
  const __m128d ey = _mm_and_pd(positive, _mm_div_pd(qy, rho));
  const __m128d ez = _mm_and_pd(positive, _mm_div_pd(qz, rho));
  const __m128d b1x = both(f.b1.x()), b1y = both(f.b1.y()), b1z = both(f.b1.z());
  const __m128d b2x = both(f.b2.x()), b2y = both(f.b2.y()), b2z = both(f.b2.z());
  const __m128d eb1 = dot(ex, ey, ez, b1x, b1y, b1z);
  const __m128d eb2 = dot(ex, ey, ez, b2x, b2y, b2z);
  const __m128d minus_h = neg(h);
  const __m128d off = _mm_sub_pd(rho, both(f.radius));  // rho - radius
  __m128d r;
  if (P == 5 && f.sin_angle == 0.0 && f.cos_angle == 1.0) {
    store(neg(eb1), 0);
    store(neg(eb2), 1);
    store(_mm_mul_pd(minus_h, eb1), 2);
    store(_mm_mul_pd(minus_h, eb2), 3);
    store(both(-1.0), 4);
    r = off;
  } else {
    const __m128d c = both(f.cos_angle), s = both(f.sin_angle);
    const __m128d minus_c = both(-f.cos_angle);
    const __m128d hc = _mm_mul_pd(minus_h, c);  // -h cos
    store(_mm_mul_pd(minus_c, eb1), 0);
    store(_mm_mul_pd(minus_c, eb2), 1);
    store(_mm_sub_pd(_mm_mul_pd(hc, eb1), _mm_mul_pd(s, dot(vx, vy, vz, b1x, b1y, b1z))), 2);
    store(_mm_sub_pd(_mm_mul_pd(hc, eb2), _mm_mul_pd(s, dot(vx, vy, vz, b2x, b2y, b2z))), 3);
    store(minus_c, 4);
    if constexpr (P == 6) store(_mm_sub_pd(_mm_mul_pd(neg(off), s), _mm_mul_pd(h, c)), 5);
    r = _mm_sub_pd(_mm_mul_pd(off, c), _mm_mul_pd(h, s));
  }
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, r);
  *r0 = lanes[0];
  *r1 = lanes[1];
#else
  *r0 = AxialResidual<P>(f, p0, row0);
  *r1 = AxialResidual<P>(f, p1, row1);
#endif
}

// Axis point and radius from an algebraic circle fit of the points projected
// along `axis` (seed 002); origin = the axis point nearest `centroid`.
// Returns false if the projected points are too few or collinear.
bool FitCrossSection(const FitInput& input, const Eigen::Vector3d& centroid,
                     const Eigen::Vector3d& axis, AxialSurface* out);

// Levenberg–Marquardt refinement of `s` (in place) over origin (2 values,
// across the axis), axis (2), radius and, if fit_angle, angle. The origin is
// then moved along the axis to the point nearest `centroid`.
LmOutcome RefineAxial(const FitInput& input, const Eigen::Vector3d& centroid, bool fit_angle,
                      const FitParams& params, AxialSurface* s);

// Σ w r² of `s` over the input (the refinement's cost).
double AxialCost(const FitInput& input, const AxialSurface& s);

// Refines every start with RefineAxial (or, without params.refine, only
// scores it) and sets *best to the one of least cost and *iterations to its
// LM iterations. Returns that cost; +inf if `starts` is empty.
double BestAxialFit(const FitInput& input, const Eigen::Vector3d& centroid,
                    std::span<const AxialSurface> starts, bool fit_angle,
                    const FitParams& params, AxialSurface* best, int* iterations);

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_AXIAL_FIT_H_
