// The B-rep vertex of each corner cluster (topology.h: corners joined by
// junction artifacts): the point nearest the mesh corner that lies on the
// surfaces of all the cluster's regions, by Gauss-Newton on the signed
// distances with a small pull towards the start (it fixes the directions the
// surfaces leave free: two surfaces meet in a curve, tangent ones in a
// band). Three transversal surfaces give their exact common point. Once the
// edges are chosen, a corner where exact edges end moves onto them.
#ifndef MESHSEG_SRC_BREP_CORNER_POINTS_H_
#define MESHSEG_SRC_BREP_CORNER_POINTS_H_

#include <span>
#include <vector>

#include <Eigen/Core>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

// Returns the point near `start` closest to lying on every surface of
// `surfaces` (null handles skipped); `start` when none is given or the
// iteration leaves the ball of radius `max_move` around it.
Eigen::Vector3d CornerPoint(const Eigen::Vector3d& start,
                            std::span<const Handle(Geom_Surface)> surfaces, double max_move);

// Returns the point near `start` with the least sum of squared distances to
// `curves` (the exact edges ending at a corner): their common point where
// they cross, the middle of their closest points where they only touch (the
// edges along a tangent fillet); `start` when the iteration leaves the ball
// of radius `max_move`.
Eigen::Vector3d CornerOnCurves(const Eigen::Vector3d& start,
                               std::span<const Handle(Geom_Curve)> curves, double max_move);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_CORNER_POINTS_H_
