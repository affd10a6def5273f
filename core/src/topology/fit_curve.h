// A line or circle fitted to the vertices of a boundary curve, for curves
// whose surfaces have no closed-form intersection, and the distance of the
// vertices from a curve geometry.
#ifndef MESHSEG_SRC_TOPOLOGY_FIT_CURVE_H_
#define MESHSEG_SRC_TOPOLOGY_FIT_CURVE_H_

#include <optional>
#include <span>

#include <Eigen/Core>

#include "meshseg/topology.h"

namespace meshseg::topology_internal {

// Returns the least-squares line through `points` (principal axis), or
// nullopt for fewer than two distinct points.
std::optional<CurveGeometry> FitLine(std::span<const Eigen::Vector3d> points);

// Returns the circle in the least-squares plane of `points` fitted
// algebraically (Kåsa) in that plane, or nullopt for fewer than three points
// or (nearly) collinear ones.
std::optional<CurveGeometry> FitCircle(std::span<const Eigen::Vector3d> points);

// Returns the max distance of `points` from the line or circle `g` (0 for a
// polyline).
double MaxDeviation(const CurveGeometry& g, std::span<const Eigen::Vector3d> points);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_FIT_CURVE_H_
