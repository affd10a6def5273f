// Supports on a regular grid, for the tests of the steps after the covering.
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_GRID_SUPPORTS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_GRID_SUPPORTS_H_

#include <vector>

#include "reconstruct/local_fit.h"

namespace meshseg::test {

// Supports at the nodes of an n³ grid over [−extent, extent]³, radius 1.5 ×
// the grid step, each with g(x) = 1 − x·c/|c| (a sphere of radius 1, positive
// inside, to first order at c).
inline std::vector<reconstruct_internal::Support> GridSupports(int n, double extent) {
  std::vector<reconstruct_internal::Support> out;
  const double step = 2 * extent / (n - 1);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        reconstruct_internal::Support s;
        s.center = Eigen::Vector3d(i, j, k) * step - Eigen::Vector3d::Constant(extent);
        s.radius = 1.5 * step;
        const double len = s.center.norm();
        s.m = len > 0 ? Eigen::Vector3d(-s.center / len) : Eigen::Vector3d::UnitZ();
        s.d = len > 0 ? Eigen::Vector3d(s.center / len) : Eigen::Vector3d(0, 0, -1);
        s.point_count = 20;
        out.push_back(s);
      }
    }
  }
  return out;
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_GRID_SUPPORTS_H_
