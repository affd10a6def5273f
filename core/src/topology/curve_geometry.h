// The geometry reported for a boundary curve: the closed-form intersection of
// its two regions' surfaces if the mesh curve lies within tolerance of it,
// else a fitted line, else a fitted circle, else the polyline itself.
#ifndef MESHSEG_SRC_TOPOLOGY_CURVE_GEOMETRY_H_
#define MESHSEG_SRC_TOPOLOGY_CURVE_GEOMETRY_H_

#include <span>

#include <Eigen/Core>

#include "meshseg/surface.h"
#include "meshseg/topology.h"
#include "topology/surface_intersection.h"

namespace meshseg::topology_internal {

// Returns the geometry of the curve through `points` (in curve order; a
// closed curve repeats its first point). `left` / `right` are the regions'
// surfaces, nullptr at a border. Lines point along the curve order, circle
// normals see the curve run counterclockwise.
CurveGeometry CurveGeometryOf(std::span<const Eigen::Vector3d> points, const Surface* left,
                              const Surface* right, const IntersectionTolerances& tol);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_CURVE_GEOMETRY_H_
