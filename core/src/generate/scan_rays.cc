#include "generate/scan_rays.h"

#include <algorithm>

namespace meshseg::generate_internal {

bool LineOfSight(const Csg& solid, const Eigen::Vector3d& surface_point, const Eigen::Vector3d& eye,
                 double start, double h) {
  const Eigen::Vector3d ray = eye - surface_point;
  const double length = ray.norm();
  const Eigen::Vector3d dir = ray / length;
  const double min_step = kMinStepVoxels * h;
  double t = start;
  for (int step = 0; step < kMaxSteps && t < length; ++step) {
    const double f = solid.Eval(surface_point + t * dir).f;
    if (f < -kBlockedDepthVoxels * h) return false;
    t += std::max(f, min_step);
  }
  return t >= length;
}

}  // namespace meshseg::generate_internal
