// Rounds between two flat faces (our addition to ALGORITHMS.md S1 and S2,
// after S2's fillet recognition FLT3). A round is tangent to the faces it
// joins by design, but a cylinder fitted alone to its region gets all five
// of its values from a narrow arc: at sigma = 0.15 h a round of r 4 between
// two planes (a 65-degree arc, 11 voxels) kept a 55-degree arc of it after
// the tangent rows went to the planes (both fit those rows within the noise)
// and came out r 3.74 to 4.28, 0.75 h off; fitted tangent to the two planes,
// the radius is the one value left and the planes' thousands of vertices fix
// the rest.
#ifndef MESHSEG_SRC_SEGMENT_TANGENT_ROUNDS_H_
#define MESHSEG_SRC_SEGMENT_TANGENT_ROUNDS_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// For every cylinder region, each pair of plane regions around it whose
// normals are within kCoaxialMaxAngleDeg of square to its axis and at least
// kMinRoundAngleDeg apart is a candidate: the cylinder tangent to both
// (FitCylinderTangentToPlanes, on the side of each its own axis lies on) is
// fitted to its interior vertices (InteriorVertices) that meet (5) and (6)
// for its surface (sub-sampled), and the best pair's fit is refitted with
// the planes on the vertices of the round's arc and beyond its lines of
// contact (FitRoundOnArc, round_arc.h). It replaces the surface if, on the
// arc's vertices and the region's own between its lines of contact (those
// beyond one are the face's by position, and pull a free cylinder out to
// them), it raises the sum of squared distances by at most
// kCoaxialChiSquare times the residual variance of the cylinder fitted
// freely to the same vertices (over the 18 rounds of three noise draws of
// a part with six rounds at sigma = 0.15 h: 3.9 on average, 4 expected),
// and E, with the tangent round's kTangentRoundParameters against the free
// cylinder's five, is not higher; the region then shares the other four
// with the planes (RegionState::shared_parameters). Tangency fixes the
// same 4 values (axis direction and position) an axis shared with a
// coaxial neighbour does, so a round that meets a face at an angle (a
// cylinder cut by a plane, not blended into it) keeps its own. Returns the
// ids of the regions whose surface changed.
std::vector<int> FitRoundsTangentToPlanes(const SegmentContext& c, const std::vector<int>& labels,
                                          std::vector<RegionState>* regions);

// Planes closer than this to parallel have no line for a round to follow.
inline constexpr double kMinRoundAngleDeg = 10.0;
// The values of a round tangent to two planes fitted to its own vertices:
// its radius (the axis is the planes').
inline constexpr int kTangentRoundParameters = 1;

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_TANGENT_ROUNDS_H_
