// Shared by the cylinder and cone fits: surfaces whose generator, in the
// half-plane through the axis, is the line rho = radius + h tan(angle)
// (h along the axis from `origin`, rho the distance from the axis). The
// cylinder is angle = 0. Geometric residual (signed distance to the
// generator line): r = (rho - radius) cos(angle) - h sin(angle).
#ifndef MESHSEG_SRC_FIT_AXIAL_FIT_H_
#define MESHSEG_SRC_FIT_AXIAL_FIT_H_

#include <span>

#include <Eigen/Core>

#include "fit/axial_lanes.h"
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
  using namespace lanes;
  auto store = [&](__m128d x, int k) { Store(x, &(*row0)(k), &(*row1)(k)); };
  const AxialPair a(f.origin, f.axis, p0, p1);
  const __m128d eb1 = Dot(a.ex, a.ey, a.ez, f.b1);
  const __m128d eb2 = Dot(a.ex, a.ey, a.ez, f.b2);
  const __m128d minus_h = Negated(a.h);
  const __m128d off = _mm_sub_pd(a.rho, Both(f.radius));  // rho - radius
  __m128d r;
  if (P == 5 && f.sin_angle == 0.0 && f.cos_angle == 1.0) {
    store(Negated(eb1), 0);
    store(Negated(eb2), 1);
    store(_mm_mul_pd(minus_h, eb1), 2);
    store(_mm_mul_pd(minus_h, eb2), 3);
    store(Both(-1.0), 4);
    r = off;
  } else {
    const __m128d c = Both(f.cos_angle), s = Both(f.sin_angle);
    const __m128d minus_c = Both(-f.cos_angle);
    const __m128d hc = _mm_mul_pd(minus_h, c);  // -h cos
    store(_mm_mul_pd(minus_c, eb1), 0);
    store(_mm_mul_pd(minus_c, eb2), 1);
    store(_mm_sub_pd(_mm_mul_pd(hc, eb1), _mm_mul_pd(s, Dot(a.vx, a.vy, a.vz, f.b1))), 2);
    store(_mm_sub_pd(_mm_mul_pd(hc, eb2), _mm_mul_pd(s, Dot(a.vx, a.vy, a.vz, f.b2))), 3);
    store(minus_c, 4);
    if constexpr (P == 6) store(_mm_sub_pd(_mm_mul_pd(Negated(off), s), _mm_mul_pd(a.h, c)), 5);
    r = _mm_sub_pd(_mm_mul_pd(off, c), _mm_mul_pd(a.h, s));
  }
  Store(r, r0, r1);
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
