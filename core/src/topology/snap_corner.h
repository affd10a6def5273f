// The common point of three or more surfaces near a corner vertex, found by
// Gauss–Newton on their signed distances (closest points from the fit
// stage's Project). Surfaces that are tangent or whose normals are (nearly)
// coplanar do not meet in one point; the corner then keeps its vertex.
#ifndef MESHSEG_SRC_TOPOLOGY_SNAP_CORNER_H_
#define MESHSEG_SRC_TOPOLOGY_SNAP_CORNER_H_

#include <optional>
#include <span>

#include <Eigen/Core>

#include "meshseg/surface.h"

namespace meshseg::topology_internal {

// Returns the point on all `surfaces` nearest to `start`, if they meet in
// one point within `max_distance` of it; nullopt for fewer than three
// surfaces, normals spanning less than 3D there, or no convergence.
std::optional<Eigen::Vector3d> SnapCorner(const Eigen::Vector3d& start,
                                          std::span<const Surface* const> surfaces,
                                          double max_distance);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_SNAP_CORNER_H_
