// Value, gradient and closest point of the general quadric of seed 000 eq. (7).
#ifndef MESHSEG_SRC_FIT_PROJECT_QUADRIC_H_
#define MESHSEG_SRC_FIT_PROJECT_QUADRIC_H_

#include <Eigen/Core>

#include "meshseg/fit.h"

namespace meshseg::fit_internal {

// f(x) of seed 000 eq. (7).
double QuadricValue(const Quadric& q, const Eigen::Vector3d& x);

// ∇f(x).
Eigen::Vector3d QuadricGradient(const Quadric& q, const Eigen::Vector3d& x);

// Seed 000 §5: three times, intersect the line through p along d_k with the
// quadric (root of smallest |t|; without a real root, one gradient step
// |f| / |∇f| from the current foot point), then d_{k+1} = ∇f at the new foot.
// d_0 = hint (if non-zero) else ∇f(p). Normal = ∇f / |∇f| at the foot point;
// distance = (p - foot) · normal.
Projection ProjectQuadric(const Quadric& q, const Eigen::Vector3d& p,
                          const Eigen::Vector3d& hint);

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_PROJECT_QUADRIC_H_
