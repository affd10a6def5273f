// The partition-of-unity implicit f(x) = Σ w_i(x) g_i(x) / Σ w_i(x),
// positive inside. Seed 001 eq. (1).
#ifndef MESHSEG_RECONSTRUCT_PU_FUNCTION_H_
#define MESHSEG_RECONSTRUCT_PU_FUNCTION_H_

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "reconstruct/local_fit.h"
#include "mesh/point_index.h"

namespace meshseg::reconstruct_internal {

class PuFunction {
 public:
  // `supports` must outlive this object.
  explicit PuFunction(const std::vector<Support>& supports);

  // Returns f(x); −(largest radius) where no support reaches x (outside).
  // Thread-safe.
  double operator()(const Eigen::Vector3d& x) const;

 private:
  // Supports grouped by radius in [2^c, 2^(c+1)) × smallest radius, so one
  // radius query per group finds all balls containing x.
  struct Group {
    std::vector<Eigen::Vector3d> centers;
    std::vector<int> support;  // index into supports_
    double max_radius = 0.0;
    std::unique_ptr<mesh_internal::PointIndex> index;
  };
  const std::vector<Support>& supports_;
  std::vector<Group> groups_;
  double largest_radius_ = 0.0;
};

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_PU_FUNCTION_H_
