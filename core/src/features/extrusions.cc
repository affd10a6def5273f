#include "features/extrusions.h"

#include <algorithm>
#include <set>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace meshseg::features_internal {
namespace {

// Candidate directions in region order, parallel ones merged.
std::vector<Eigen::Vector3d> CandidateDirections(const Topology& topology,
                                                 std::span<const Region> regions,
                                                 const Tolerances& tol) {
  std::vector<Eigen::Vector3d> out;
  auto add = [&](const Eigen::Vector3d& d) {
    for (const Eigen::Vector3d& e : out) {
      if (Parallel(d, e, tol)) return;
    }
    out.push_back(d.normalized());
  };
  for (const Region& r : regions) {
    if (const auto* c = std::get_if<Cylinder>(&r.surface)) add(c->axis_direction);
  }
  for (const Adjacency& arc : topology.adjacency) {
    const auto* a = std::get_if<Plane>(&regions[arc.region_a].surface);
    const auto* b = std::get_if<Plane>(&regions[arc.region_b].surface);
    if (a && b && !Parallel(a->normal, b->normal, tol)) add(a->normal.cross(b->normal));
  }
  return out;
}

// The direction best perpendicular to the planes' normals and parallel to
// the cylinders' axes: least eigenvector of Σ n nᵀ + Σ (I - a aᵀ).
Eigen::Vector3d RefinedDirection(std::span<const Region> regions, const std::vector<int>& members,
                                 const Eigen::Vector3d& seed) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const int r : members) {
    if (const auto* p = std::get_if<Plane>(&regions[r].surface)) {
      const Eigen::Vector3d n = p->normal.normalized();
      m += n * n.transpose();
    }
    if (const auto* c = std::get_if<Cylinder>(&regions[r].surface)) {
      const Eigen::Vector3d a = c->axis_direction.normalized();
      m += Eigen::Matrix3d::Identity() - a * a.transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  Eigen::Vector3d d = eig.eigenvectors().col(0);
  return d.dot(seed) < 0.0 ? Eigen::Vector3d(-d) : d;
}

// True if every region next to the group but not in it is a cap: a plane
// perpendicular to d (a slab of a prism, cut along another direction, has
// side walls there instead).
bool ClosedByCaps(std::span<const Region> regions, const RegionGraph& graph,
                  const std::vector<char>& member, const std::vector<int>& group,
                  const Eigen::Vector3d& d, const Tolerances& tol) {
  for (const int r : group) {
    for (const int n : graph.Neighbors(r)) {
      if (member[n]) continue;
      const auto* p = std::get_if<Plane>(&regions[n].surface);
      if (!p || !Parallel(p->normal, d, tol)) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<Feature> FindExtrusions(const Topology& topology, std::span<const Region> regions,
                                    const RegionGraph& graph, const Tolerances& tol) {
  std::vector<Feature> out;
  std::set<std::vector<int>> found;
  for (const Eigen::Vector3d& d : CandidateDirections(topology, regions, tol)) {
    std::vector<char> member(regions.size(), 0);
    for (size_t r = 0; r < regions.size(); ++r) {
      if (const auto* p = std::get_if<Plane>(&regions[r].surface)) {
        member[r] = Perpendicular(p->normal, d, tol);
      }
      if (const auto* c = std::get_if<Cylinder>(&regions[r].surface)) {
        member[r] = Parallel(c->axis_direction, d, tol);
      }
    }
    for (std::vector<int>& group : graph.Components(member)) {
      const auto planes = std::count_if(group.begin(), group.end(), [&](int r) {
        return std::holds_alternative<Plane>(regions[r].surface);
      });
      const auto cylinders = static_cast<long>(group.size()) - planes;
      if (group.size() < 3 || (planes < 3 && cylinders < 2)) continue;
      if (!ClosedByCaps(regions, graph, member, group, d, tol)) continue;
      if (!found.insert(group).second) continue;
      Feature f;
      f.type = FeatureType::kLinearExtrusion;
      f.direction = RefinedDirection(regions, group, d);
      f.regions = std::move(group);
      out.push_back(std::move(f));
    }
  }
  return out;
}

}  // namespace meshseg::features_internal
