// One support ball of the partition of unity: its radius by bisection against
// the error tolerance and its linear local function. Seed 001 eqs. (2)-(6).
#ifndef MESHSEG_RECONSTRUCT_LOCAL_FIT_H_
#define MESHSEG_RECONSTRUCT_LOCAL_FIT_H_

#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"

namespace meshseg::reconstruct_internal {

// A support ball s_i and its local function g_i(x) = m · (x − d).
struct Support {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // c_i
  double radius = 0.0;                               // r_i
  Eigen::Vector3d m = Eigen::Vector3d::UnitZ();      // unit, inward
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  int point_count = 0;  // input points with |p − c| < r

  double g(const Eigen::Vector3d& x) const { return m.dot(x - d); }
};

// Quadratic B-spline b2 of seed 001 eq. (5).
inline double B2(double t) {
  if (t >= 1.5) return 0.0;
  if (t >= 0.5) return 0.5 * (1.5 - t) * (1.5 - t);
  return 0.75 - t * t;
}

// Weight w_i(x) = b2(3|x − c| / 2r) of seed 001 eq. (4), from |x − c|².
inline double SupportWeight(double dist2, double radius) {
  return B2(1.5 * std::sqrt(dist2) / radius);
}

// The input the local fits read; all references outlive the fits.
struct FitInput {
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<Eigen::Vector3d>& normals;  // unit, inward
  const mesh_internal::PointIndex& index;
  double epsilon;     // ε, model units
  double max_radius;  // never grow a ball beyond this
};

// Minimum number of points (the farthest with zero weight) a ball holds so
// that g_i is defined; balls in empty space grow until they hold as many.
inline constexpr int kMinFitPoints = 6;

// Returns the support centred at `center` whose radius is the largest with
// max |g(p_j)| ≤ ε over the points inside (eq. 6, bisection), but at least
// `min_radius` (0.75 × cell diagonal) and large enough to hold kMinFitPoints.
Support FitSupport(const Eigen::Vector3d& center, double min_radius, const FitInput& in);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_LOCAL_FIT_H_
