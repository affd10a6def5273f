// Intersections of lines and circles in a plane. The analytic intersection of
// two surfaces reduces to this 2D problem in a meridian half-plane (coaxial
// surfaces of revolution: the profiles of plane, cylinder, cone, sphere,
// torus) or in a cross-section (surfaces extruded along one direction: plane
// and cylinder). Tangent profiles (fillets) meet in their touching point.
#ifndef MESHSEG_SRC_TOPOLOGY_PROFILE_INTERSECTION_H_
#define MESHSEG_SRC_TOPOLOGY_PROFILE_INTERSECTION_H_

#include <optional>

#include <Eigen/Core>

namespace meshseg::topology_internal {

// A line (point, unit direction) or a circle (centre, radius) in 2D.
struct Profile {
  bool is_circle = false;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // lines only, unit
  double radius = 0.0;                                   // circles only
};

// Returns the intersection point of `a` and `b` nearest to `near`. Profiles
// that miss each other by at most `tangent_tolerance` count as tangent and
// meet midway between their closest points. nullopt for parallel lines or
// profiles further apart.
std::optional<Eigen::Vector2d> IntersectProfiles(const Profile& a, const Profile& b,
                                                 const Eigen::Vector2d& near,
                                                 double tangent_tolerance);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_PROFILE_INTERSECTION_H_
