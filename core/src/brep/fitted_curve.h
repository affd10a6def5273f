// The edge curve of a boundary whose surfaces have no usable intersection
// (tangent surfaces of a fillet, surfaces that miss each other by the noise,
// the mesh border): the boundary polyline drawn onto both surfaces (each
// point moved to the midpoint of its projections, repeatedly) and fitted by
// a line, a circular arc or a smoothing B-spline, whichever first follows
// it within the tolerance; a spline no longer than the polyline plus the
// tolerance at each end (else it doubles back on itself).
#ifndef MESHSEG_SRC_BREP_FITTED_CURVE_H_
#define MESHSEG_SRC_BREP_FITTED_CURVE_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/topology.h"

#include <optional>
#include <span>

#include <Eigen/Core>
#include <Geom_Surface.hxx>

#include "brep/trim_curve.h"

namespace meshseg::brep_internal {

// Returns the fitted curve of the boundary `polyline` between `left` and
// `right` (null at the border), ending exactly at `start` and `end` (unset
// for a closed boundary). `hint` is the topology stage's fitted line or
// circle; `tolerance` the accepted deviation from the polyline; `l_avg`
// the mesh's mean edge length. nullopt for a degenerate polyline, or when
// no spline runs along it.
std::optional<TrimmedCurve> FitEdgeCurve(std::span<const Eigen::Vector3d> polyline,
                                         const Handle(Geom_Surface) & left,
                                         const Handle(Geom_Surface) & right,
                                         const std::optional<Eigen::Vector3d>& start,
                                         const std::optional<Eigen::Vector3d>& end,
                                         const CurveGeometry& hint, double tolerance,
                                         double l_avg);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_FITTED_CURVE_H_
