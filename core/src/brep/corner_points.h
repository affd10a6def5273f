// The B-rep vertex of each corner cluster (topology.h: corners joined by
// junction artifacts): the point nearest the mesh corner that lies on the
// surfaces of all the cluster's regions, by Gauss-Newton on the signed
// distances. Along a direction the surfaces leave free (two surfaces meet in
// a curve) or fix only within their fit error (tangent surfaces, whose
// crossing a small offset moves far) the corner stays where the mesh puts
// it. Three transversal surfaces give their exact common point. Once the
// edges are chosen, a corner where exact edges end moves onto them, by the
// same rule.
#ifndef MESHSEG_SRC_BREP_CORNER_POINTS_H_
#define MESHSEG_SRC_BREP_CORNER_POINTS_H_

#include <span>
#include <vector>

#include <Eigen/Core>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

// What decides which directions the surfaces fix: a direction along which
// moving the corner by `spacing` (how well the mesh places it: about one
// mesh edge) changes the distances to the surfaces by less than
// `surface_offset` (how far a fitted surface may lie off the true one) is
// left at the start. Two surfaces crossing at angle theta fix the direction
// across their curve when sin(theta) * spacing > surface_offset, roughly.
struct CornerNoise {
  double surface_offset = 0.0;
  double spacing = 1.0;
};

// Returns the point near `start` closest to lying on every surface of
// `surfaces` (null handles skipped); `start` when none is given or the
// iteration leaves the ball of radius `max_move` around it. Along a
// direction the surfaces do not fix (CornerNoise) the point keeps the
// start's coordinate.
Eigen::Vector3d CornerPoint(const Eigen::Vector3d& start,
                            std::span<const Handle(Geom_Surface)> surfaces, double max_move,
                            const CornerNoise& noise = {});

// Returns the point near `start` with the least sum of squared distances to
// `curves` (the exact edges ending at a corner): their common point where
// they cross, the middle of their closest points where they only touch (the
// edges along a tangent fillet); `start` when the iteration leaves the ball
// of radius `max_move`. Curves running nearly parallel leave the point at
// the start's coordinate along them, as CornerPoint.
Eigen::Vector3d CornerOnCurves(const Eigen::Vector3d& start,
                               std::span<const Handle(Geom_Curve)> curves, double max_move,
                               const CornerNoise& noise = {});

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_CORNER_POINTS_H_
