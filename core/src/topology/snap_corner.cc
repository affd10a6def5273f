#include "topology/snap_corner.h"

#include <Eigen/Dense>

#include "meshseg/fit.h"

namespace meshseg::topology_internal {
namespace {

// Smallest singular value of the unit-normal Jacobian for which the surfaces
// count as meeting transversally in a point (normals at least ~6° out of
// any common plane).
constexpr double kMinSingularValue = 0.1;
constexpr int kMaxIterations = 30;

}  // namespace

std::optional<Eigen::Vector3d> SnapCorner(const Eigen::Vector3d& start,
                                          std::span<const Surface* const> surfaces,
                                          double max_distance) {
  if (surfaces.size() < 3) return std::nullopt;
  const Eigen::Index k = static_cast<Eigen::Index>(surfaces.size());
  Eigen::Vector3d x = start;
  Eigen::MatrixXd jacobian(k, 3);
  Eigen::VectorXd residual(k);
  const double step_tolerance = 1e-9 * (1.0 + max_distance);
  for (int it = 0; it < kMaxIterations; ++it) {
    for (Eigen::Index i = 0; i < k; ++i) {
      const Projection p = Project(*surfaces[i], x);
      jacobian.row(i) = p.normal.transpose();
      residual(i) = p.distance;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian,
                                                Eigen::ComputeThinU | Eigen::ComputeThinV);
    if (svd.singularValues()(2) < kMinSingularValue) return std::nullopt;
    const Eigen::Vector3d step = -svd.solve(residual);
    x += step;
    if ((x - start).norm() > max_distance) return std::nullopt;
    // Converged; more than three surfaces must also really share the point.
    if (step.norm() < step_tolerance) {
      if (residual.cwiseAbs().maxCoeff() > 1e-3 * max_distance) return std::nullopt;
      return x;
    }
  }
  return std::nullopt;
}

}  // namespace meshseg::topology_internal
