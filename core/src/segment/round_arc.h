// The vertices of a round between two flat faces, taken by position (our
// addition to ALGORITHMS.md S1 and S2, for tangent_rounds.h).
// Near a line of contact a vertex lies within the noise of both the round
// and the face, and the labelling gives it to the nearer surface, which its
// noise decides: inside the arc the face's extension lies outside the
// round, so the round keeps the vertices the noise pushed in and loses
// those it pushed out, and its vertices sit inside the true round near both
// edges. At sigma = 0.15 h the true cylinder of a 65-degree round of r 4
// missed its region's vertices by 18.9 residual variances more than the
// free fit (about 4 expected), and the tangent fit was refused. A vertex's
// angle around the round's axis does not depend on its radial noise: the
// round is fitted to the vertices of the round and both faces that lie on
// its arc by angle, each face to the vertices beyond its line of contact.
#ifndef MESHSEG_SRC_SEGMENT_ROUND_ARC_H_
#define MESHSEG_SRC_SEGMENT_ROUND_ARC_H_

#include <array>
#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// A round tangent to two planes and the vertices it was fitted on.
struct RoundOnArc {
  FitResult round;              // the tangent cylinder
  std::array<Plane, 2> planes;  // each fitted beyond its line of contact
  std::vector<int> arc;         // the vertices on the round's arc, sorted
  // The round region's own vertices between its lines of contact (at any
  // distance from it), sorted; those beyond either are a face's by position.
  std::vector<int> inside;
};

// Fits the round of region `round_id`, tangent to the planes of regions
// `face_ids`, starting from `tangent` (a cylinder tangent to both). Then,
// in turn: the arc is the vertices of the three regions whose direction
// from the axis lies between the two lines of contact, within the round's
// extent along the axis and within th_dis of it; each face's plane is
// refitted to the vertices of the three regions beyond its line of contact
// that meet (5) and (6) for it (the rows within the tolerance of both
// surfaces dip under the plane inside the arc and say nothing about where
// it is); the round is refitted tangent to both on the arc. Stops when the
// arc repeats or after kMaxArcTurns turns (against cycling between two
// sets); `inside` is taken with the last arc. Only measured vertices
// (SegmentParams::measured) are sorted: a closing patch says nothing of where
// the round or its faces lie. Invalid if a fit fails or a set has too few
// vertices.
RoundOnArc FitRoundOnArc(const SegmentContext& c, const std::vector<RegionState>& regions,
                         int round_id, std::array<int, 2> face_ids, const Cylinder& tangent);

inline constexpr int kMaxArcTurns = 8;

// +1 if `p` lies on the side of `plane` its normal points to, else -1.
int PlaneSide(const Plane& plane, const Eigen::Vector3d& p);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ROUND_ARC_H_
