// The closed-form intersection curve of two fitted surfaces, where one
// exists: a circle for coaxial surfaces of revolution (a plane perpendicular
// to a cylinder, cone, sphere or torus axis; coaxial cylinder/cone/torus;
// sphere centres on the axis) and a line for surfaces extruded along one
// direction (two planes; a plane parallel to a cylinder axis; parallel
// cylinders). Tangent surfaces (fillets) give their line/circle of contact.
#ifndef MESHSEG_SRC_TOPOLOGY_SURFACE_INTERSECTION_H_
#define MESHSEG_SRC_TOPOLOGY_SURFACE_INTERSECTION_H_

#include <optional>
#include <span>

#include <Eigen/Core>

#include "meshseg/surface.h"
#include "meshseg/topology.h"

namespace meshseg::topology_internal {

struct IntersectionTolerances {
  double angle_rad = 0.0;  // axes/normals parallel or perpendicular within this
  double distance = 0.0;   // axes coincide / profiles touch within this
};

// Returns the line or circle where `a` and `b` meet nearest to `points` (the
// mesh curve), with analytic = true; direction and max_deviation are left
// for the caller. nullopt when no closed form applies or the surfaces miss.
std::optional<CurveGeometry> IntersectSurfaces(const Surface& a, const Surface& b,
                                               std::span<const Eigen::Vector3d> points,
                                               const IntersectionTolerances& tol);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_SURFACE_INTERSECTION_H_
