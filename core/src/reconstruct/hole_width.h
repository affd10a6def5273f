// How wide the hole is that a handle's loop goes round (issue 38 item 1; the
// slit test of handle_strips.h, our addition to ALGORITHMS.md S3).
//
// Principle: a hole is as wide as the largest ball that fits in it, centred
// on a surface spanning the loop, that the loop does not enter: the diameter
// of the hole's inscribed circle. A round hole d across reads d, a slit (two
// long sides a gap g apart) reads g, whatever the loop's length; the bound
// of the handle step (handles.h) is on exactly that width, the gap the points
// cannot show (handle_spacings × s). The spanning surface is the loop's
// least-area disc, approximated by the least-area triangulation over the
// loop's own vertices (Barequet & Sharir 1995; the weight of Liepa 2003's
// hole triangulation taken as area): it is the plane polygon for a flat
// loop, and on a loop that is not flat (a hole's rim running up and down a
// curved wall, a slit in a bent sheet) it still spans the hole, not a
// projection of it.
//
// 4 A / L (vector area over length) reads a circle's diameter too, but a
// loop that is not flat has a smaller vector area and a longer length than
// the hole it goes round, so a long, non-flat loop read narrower than its
// hole; it read a slit as twice its gap.
#ifndef MESHSEG_RECONSTRUCT_HOLE_WIDTH_H_
#define MESHSEG_RECONSTRUCT_HOLE_WIDTH_H_

#include <array>
#include <functional>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// The least-area triangulation of the closed polygon `loop` over its own
// vertices (n − 2 triangles of indices into `loop`; none for n < 3): dynamic
// programming over the polygon's sub-chains, O(n³) time, O(n²) memory.
std::vector<std::array<int, 3>> LeastAreaDisc(const std::vector<Eigen::Vector3d>& loop);

// The diameter of the largest ball centred on LeastAreaDisc(loop) that the
// polygon `loop` does not enter (model units); 0 for fewer than 3 vertices
// or no positive `step`. The disc's triangles are sampled in rows `step`
// apart, `step` apart along each row; every point of a triangle lies within
// √5 / 2 steps of a sample, and the distance to the polygon changes by no
// more than the distance moved, so the sampled radius is raised by that
// much: the width returned is never below the disc's true one and at most
// 2.24 steps above it. It returns as soon as that bound exceeds `stop`,
// with a value above `stop` (not the full width): the hole is then not known
// to be at most `stop` across.
//
// With `clearance` (the distance from a point to the nearest of other things
// the ball may not enter either, 1-Lipschitz like the distance to the loop),
// the ball keeps clear of those as well: the hole as the scan points show it
// (handle_strips.h), whose void no point lies in.
using Clearance = std::function<double(const Eigen::Vector3d&)>;
double HoleWidth(const std::vector<Eigen::Vector3d>& loop, double step,
                 double stop = std::numeric_limits<double>::infinity(),
                 const Clearance& clearance = nullptr);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_HOLE_WIDTH_H_
