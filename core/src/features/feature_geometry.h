// Geometric predicates the feature rules share: parallel and perpendicular
// directions, coincident axes of cylinders/cones/tori, and the region
// adjacency graph with its curves.
#ifndef MESHSEG_SRC_FEATURES_FEATURE_GEOMETRY_H_
#define MESHSEG_SRC_FEATURES_FEATURE_GEOMETRY_H_

#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "meshseg/segment.h"
#include "meshseg/topology.h"

namespace meshseg::features_internal {

struct Tolerances {
  double angle_rad = 0.0;  // parallel / perpendicular within this
  double distance = 0.0;   // model units
};

// AxisLine and AxisOf are in meshseg/surface.h.

bool Parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Tolerances& tol);
bool Perpendicular(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Tolerances& tol);
double DistanceToLine(const Eigen::Vector3d& p, const AxisLine& axis);
// Parallel and through the same points (within tol.distance).
bool SameAxis(const AxisLine& a, const AxisLine& b, const Tolerances& tol);

// The unit normal of a plane region pointing out of the solid.
Eigen::Vector3d OutwardNormal(const Plane& plane, const RegionTopology& region);

// The region adjacency graph of a Topology.
class RegionGraph {
 public:
  explicit RegionGraph(const Topology& topology);

  // Neighbours of region r (ids >= 0), ascending.
  const std::vector<int>& Neighbors(int r) const { return neighbors_[r]; }
  // True if every curve between a and b is smooth (not sharp) and there is one.
  bool TangentBetween(int a, int b) const;
  // Connected components of the regions r with member[r] != 0, joined
  // through adjacency among members only; each ascending, ordered by their
  // smallest region.
  std::vector<std::vector<int>> Components(const std::vector<char>& member) const;

 private:
  const Topology& topology_;
  std::vector<std::vector<int>> neighbors_;
  std::map<std::pair<int, int>, const Adjacency*> arcs_;
};

}  // namespace meshseg::features_internal

#endif  // MESHSEG_SRC_FEATURES_FEATURE_GEOMETRY_H_
