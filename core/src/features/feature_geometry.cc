#include "features/feature_geometry.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace meshseg::features_internal {

bool Parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Tolerances& tol) {
  return std::abs(a.normalized().dot(b.normalized())) >= std::cos(tol.angle_rad);
}

bool Perpendicular(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Tolerances& tol) {
  return std::abs(a.normalized().dot(b.normalized())) <= std::sin(tol.angle_rad);
}

double DistanceToLine(const Eigen::Vector3d& p, const AxisLine& axis) {
  const Eigen::Vector3d v = p - axis.point;
  return (v - v.dot(axis.direction) * axis.direction).norm();
}

bool SameAxis(const AxisLine& a, const AxisLine& b, const Tolerances& tol) {
  return Parallel(a.direction, b.direction, tol) && DistanceToLine(b.point, a) <= tol.distance &&
         DistanceToLine(a.point, b) <= tol.distance;
}

Eigen::Vector3d OutwardNormal(const Plane& plane, const RegionTopology& region) {
  const Eigen::Vector3d n = plane.normal.normalized();
  return region.normal_sign < 0 ? Eigen::Vector3d(-n) : n;
}

RegionGraph::RegionGraph(const Topology& topology)
    : topology_(topology), neighbors_(topology.regions.size()) {
  for (const Adjacency& arc : topology.adjacency) {
    neighbors_[arc.region_a].push_back(arc.region_b);
    neighbors_[arc.region_b].push_back(arc.region_a);
    arcs_[{arc.region_a, arc.region_b}] = &arc;
  }
  for (std::vector<int>& n : neighbors_) std::sort(n.begin(), n.end());
}

bool RegionGraph::TangentBetween(int a, int b) const {
  const auto it = arcs_.find(std::minmax(a, b));
  if (it == arcs_.end() || it->second->curves.empty()) return false;
  return std::none_of(it->second->curves.begin(), it->second->curves.end(),
                      [&](int c) { return topology_.curves[c].sharp; });
}

std::vector<std::vector<int>> RegionGraph::Components(const std::vector<char>& member) const {
  std::vector<std::vector<int>> out;
  std::vector<char> seen(member.size(), 0);
  for (int seed = 0; seed < static_cast<int>(member.size()); ++seed) {
    if (!member[seed] || seen[seed]) continue;
    std::vector<int> component;
    std::vector<int> stack = {seed};
    seen[seed] = 1;
    while (!stack.empty()) {
      const int r = stack.back();
      stack.pop_back();
      component.push_back(r);
      for (const int n : neighbors_[r]) {
        if (member[n] && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
      }
    }
    std::sort(component.begin(), component.end());
    out.push_back(std::move(component));
  }
  return out;
}

}  // namespace meshseg::features_internal
