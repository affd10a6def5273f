// The 2:1-balanced octree whose leaf centres are the candidate support
// centres of the covering. Seed 001 §2.1.2 step (1).
#ifndef MESHSEG_RECONSTRUCT_OCTREE_H_
#define MESHSEG_RECONSTRUCT_OCTREE_H_

#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"

namespace meshseg::reconstruct_internal {

struct OctreeLeaf {
  Eigen::Vector3d center;
  double size = 0.0;  // edge length
  int level = 0;
};

// Highest max_level BuildOctree accepts (21 bits per coordinate in a key).
inline constexpr int kMaxOctreeLevel = 16;

// Returns the leaves of the octree over the cube [origin, origin + size]^3
// in which every point's cell is refined to `max_level` and cells sharing a
// face, an edge or a corner differ by at most one level. Leaves are sorted
// by level, then by position. Points outside the cube are clamped into it.
// Requires 1 ≤ max_level ≤ kMaxOctreeLevel.
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<OctreeLeaf>> BalancedOctreeLeaves(
    const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& origin, double size,
    int max_level, const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_OCTREE_H_
