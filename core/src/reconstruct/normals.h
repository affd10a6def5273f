// Inward unit normals for a point cloud: estimated by k-NN PCA and oriented by
// minimum-spanning-tree propagation (Hoppe et al. 1992), or taken from the
// file and converted to the inward convention of seed 001 §2.
#ifndef MESHSEG_RECONSTRUCT_NORMALS_H_
#define MESHSEG_RECONSTRUCT_NORMALS_H_

#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/neighbors.h"

namespace meshseg::reconstruct_internal {

struct OrientedNormals {
  std::vector<Eigen::Vector3d> normals;  // one unit normal per point, inward
  bool flipped = false;                  // given normals were outward or re-oriented
};

// Returns inward unit normals for `points`. With `given` empty they are the
// least-variance directions of the k nearest neighbours (`nearest`, k =
// nearest.k), made consistent by
// propagation along a minimum spanning tree of the symmetric k-NN graph
// (weight 1 − |n_i·n_j|), one tree per connected component. Given normals
// are kept unless more than 10 % of confident neighbour pairs disagree, in
// which case they are re-oriented the same way. Each component (or the whole
// given set) is turned inward when Σ (p − centroid)·n > 0, which for a closed
// surface is 3 × volume with outward normals (divergence theorem).
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<OrientedNormals> InwardNormals(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<Eigen::Vector3d>& given,
                                              const NeighborTable& nearest, const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_NORMALS_H_
