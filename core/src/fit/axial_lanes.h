// Two points in the two lanes of SSE2 registers, for the residuals of
// surfaces about an axis computed two points at a time (AxialResidualPair,
// TorusResidualPair). Every lane runs the scalar formula's operations in
// its order: Eigen sums a Vector3d's products as (x0 + x1) + x2, and packed
// IEEE operations round each lane as scalar ones do, so each lane's value
// is the scalar value to the bit.
#ifndef MESHSEG_SRC_FIT_AXIAL_LANES_H_
#define MESHSEG_SRC_FIT_AXIAL_LANES_H_

#if defined(__SSE2__)
#include <emmintrin.h>

#include <Eigen/Core>

namespace meshseg::fit_internal::lanes {

inline __m128d Both(double x) { return _mm_set1_pd(x); }
inline __m128d Negated(__m128d x) { return _mm_xor_pd(x, _mm_set1_pd(-0.0)); }

// (x0 y0 + x1 y1) + x2 y2 per lane, as Eigen's dot of two Vector3d.
inline __m128d Dot(__m128d x0, __m128d x1, __m128d x2, __m128d y0, __m128d y1, __m128d y2) {
  return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, y0), _mm_mul_pd(x1, y1)), _mm_mul_pd(x2, y2));
}
inline __m128d Dot(__m128d x0, __m128d x1, __m128d x2, const Eigen::Vector3d& y) {
  return Dot(x0, x1, x2, Both(y.x()), Both(y.y()), Both(y.z()));
}

// Lane 0 into *a, lane 1 into *b.
inline void Store(__m128d x, double* a, double* b) {
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, x);
  *a = lanes[0];
  *b = lanes[1];
}

// Points p0 and p1 about the axis through `origin` along unit `axis`: v =
// p - origin, h = v . axis, q = v - h axis, rho = |q| and e = q / rho (0
// where rho is not positive), per lane.
struct AxialPair {
  AxialPair(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, const Eigen::Vector3d& p0,
            const Eigen::Vector3d& p1) {
    vx = _mm_sub_pd(_mm_set_pd(p1.x(), p0.x()), Both(origin.x()));
    vy = _mm_sub_pd(_mm_set_pd(p1.y(), p0.y()), Both(origin.y()));
    vz = _mm_sub_pd(_mm_set_pd(p1.z(), p0.z()), Both(origin.z()));
    h = Dot(vx, vy, vz, axis);
    const __m128d qx = _mm_sub_pd(vx, _mm_mul_pd(h, Both(axis.x())));
    const __m128d qy = _mm_sub_pd(vy, _mm_mul_pd(h, Both(axis.y())));
    const __m128d qz = _mm_sub_pd(vz, _mm_mul_pd(h, Both(axis.z())));
    rho = _mm_sqrt_pd(Dot(qx, qy, qz, qx, qy, qz));
    // The lane's 0 / 0 where rho is 0 is masked off.
    const __m128d positive = _mm_cmpgt_pd(rho, _mm_setzero_pd());
    ex = _mm_and_pd(positive, _mm_div_pd(qx, rho));
    ey = _mm_and_pd(positive, _mm_div_pd(qy, rho));
    ez = _mm_and_pd(positive, _mm_div_pd(qz, rho));
  }
  __m128d vx, vy, vz, h, rho, ex, ey, ez;
};

}  // namespace meshseg::fit_internal::lanes

#endif  // defined(__SSE2__)

#endif  // MESHSEG_SRC_FIT_AXIAL_LANES_H_
