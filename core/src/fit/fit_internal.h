// Helpers shared by the fit routines of this stage: weights, moments, frames
// perpendicular to an axis, the minimal axis update used by the
// Levenberg–Marquardt problems, and the distance errors every FitResult reports.
#ifndef MESHSEG_SRC_FIT_FIT_INTERNAL_H_
#define MESHSEG_SRC_FIT_FIT_INTERNAL_H_

#include <cstddef>

#include <Eigen/Core>

#include "meshseg/fit.h"

namespace meshseg::fit_internal {

// Weight of point i: weights[i], or 1 when no weights are given.
inline double WeightAt(const FitInput& input, std::size_t i) {
  return input.weights.empty() ? 1.0 : input.weights[i];
}

inline bool HasNormals(const FitInput& input) {
  return !input.normals.empty() && input.normals.size() == input.points.size();
}

// Weighted centroid and centred scatter matrix Σ w (p - c)(p - c)^T.
struct Moments {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  double weight_sum = 0.0;
};
Moments PointMoments(const FitInput& input);

// Σ w n n^T over the normals (the Gauss sphere's moment, not centred): its
// smallest eigenvector is the axis a cylinder's normals are perpendicular
// to (seed 002).
Eigen::Matrix3d NormalMoment(const FitInput& input);

// Eigenvalues (ascending) and eigenvectors of a symmetric 3x3 matrix.
struct Eigen3 {
  Eigen::Vector3d values = Eigen::Vector3d::Zero();
  Eigen::Matrix3d vectors = Eigen::Matrix3d::Identity();
};
Eigen3 SymmetricEigen(const Eigen::Matrix3d& m);

// A unit vector perpendicular to unit `a`, chosen deterministically.
Eigen::Vector3d AnyPerpendicular(const Eigen::Vector3d& a);

// Orthonormal b1, b2 with (b1, b2, a) right-handed; deterministic in `a`.
void PerpendicularBasis(const Eigen::Vector3d& a, Eigen::Vector3d* b1, Eigen::Vector3d* b2);

// Axis rotated by the tangent step (t1, t2) along PerpendicularBasis(a).
Eigen::Vector3d RotateAxis(const Eigen::Vector3d& a, double t1, double t2);
// The same with PerpendicularBasis(a) = (b1, b2) already at hand.
Eigen::Vector3d RotateAxis(const Eigen::Vector3d& a, const Eigen::Vector3d& b1,
                           const Eigen::Vector3d& b2, double t1, double t2);

// Sets rms_distance and max_distance of `result` from Project() of every
// input point (normals, when given, start the quadric projection).
void SetDistanceErrors(const FitInput& input, FitResult* result);

// A result with valid = false, the given surface and zero errors.
FitResult InvalidResult(const Surface& surface);

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_FIT_INTERNAL_H_
