// Rolling-ball fillets (our addition to ALGORITHMS.md S1 and S2, after S2's
// fillet recognition FLT2). A torus region grown over a small round can take
// the faces beside it and bend its tube through them: a 90-degree edge round
// (r 2 = 4 h, R 8) between a plane top and a coaxial cylinder side, at
// sigma = 0.15 h, grew over the top into a torus of r 2.87 and R 7.28 that
// cuts the top and the side at a shallow angle, and GiveBackRows then left it
// a 30-degree band, typed cone. A fillet between a plane and a coaxial
// cylinder is the torus a ball rolling along both sweeps out: tangent to
// both, its axis the cylinder's, one free parameter (the ball's radius) once
// the two faces are fitted. With each vertex taken by the nearest surface,
// the fillet of r 1.99 explains that region better than its own torus (rms
// 0.071 against 0.077, sigma 0.075).
#ifndef MESHSEG_SRC_SEGMENT_SNAP_FILLETS_H_
#define MESHSEG_SRC_SEGMENT_SNAP_FILLETS_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// The torus a ball of radius r sweeps rolling along `plane` and `cylinder`
// (whose axis should be along the plane's normal): its axis the cylinder's,
// its centre `axial` (+1 or -1) times r from the plane along the axis
// (oriented like the plane normal), its major radius the cylinder's radius
// plus `radial` (+1 or -1) times r.
Torus FilletTorus(const Plane& plane, const Cylinder& cylinder, double r, int axial, int radial);

// For every torus region whose type does not fit its interior at the noise
// (TypeMissesInterior) and that joins a cylinder coaxial with it (axes within
// kCoaxialMaxAngleDeg) and a plane across that axis, fits the fillet between
// them (its radius) to the region's vertices, each vertex taking the nearest
// of the fillet and the surfaces of the regions around it. With no such plane
// around, the region may have grown over it (a round can take the whole small
// flat face it bounds before any seed there): the plane across the axis
// through the region's vertices whose n'_i is along it stands in. If the
// fillet scores kScoreMargin better than the region's own torus on the same
// terms (InformationScore: 1 parameter, 2 with a swallowed plane, against 7),
// each vertex of the region goes to the nearest of the fillet, the surfaces
// around it and the swallowed plane (a new plane region, if it gets
// kMinRegionVertices) within th_dis, and the regions that changed are
// refitted. Nothing happens when the estimated noise is zero. Returns the
// ids of the regions that took a fillet.
std::vector<int> SnapFillets(const SegmentContext& c, std::vector<int>* labels,
                             std::vector<RegionState>* regions);


}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SNAP_FILLETS_H_
