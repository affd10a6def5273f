// Splitting a flat face off a region grown over it (our addition to
// ALGORITHMS.md S1 and S2). A small face across a crease from a curved one
// can be absorbed by it: a plane disc of radius 5 h (183 faces) on top of a
// conical frustum, at sigma = 0.15 h, has no seed that passes the plane test,
// since N'(i, W2) of every vertex on it reaches over the rim and bends n'_i;
// its vertices end in a piece of the cone, typed sphere or quadric for the
// mix, and the cone comes in pieces no type joins. The raw normals n_i still
// tell the face: on the top they scatter about its normal, on the cone they
// lie 69 degrees away.
#ifndef MESHSEG_SRC_SEGMENT_SPLIT_OFF_PLANES_H_
#define MESHSEG_SRC_SEGMENT_SPLIT_OFF_PLANES_H_

#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// For every curved or quadric region whose type does not fit its interior
// at the noise (FitsAtNoise):
//  1. takes the vertices whose n_i lie within th_nm of the direction that
//     the most n_i of the region do, fits a plane to them and then to all
//     of the region's vertices that meet (5) and (6) for it, which it must
//     fit near the noise (kScoredNearError: the rows along the crease are
//     rounded);
//  2. gives each vertex of the region to the nearer of that plane and the
//     region's type refitted to the rest, a few rounds;
//  3. keeps the split iff E (energy.h) falls: the plane joins the labels
//     as a proposal (PEARL), the expansion with re-estimation places its
//     boundary with the rest and with the neighbours, and E with the plane
//     is compared with E without it. A junction is priced, not tested: a
//     boundary through a smooth face costs lambda per edge, so rows a fillet
//     explains as well as the plane (flat-looking near its tangent line)
//     stay, and a flat face the curved fit was grown over (a top beside
//     its round, meeting it without a crease) is split off.
// A quadric region left without the plane gets the curved type that passes
// the alpha test on the rest, if any. Nothing happens when the estimated
// noise is zero. Returns the ids of the regions split (their planes are
// appended to `regions`). Errors: CANCELLED on stop.
absl::StatusOr<std::vector<int>> SplitOffPlanes(const SegmentContext& c,
                                                 std::vector<int>* labels,
                                                 std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SPLIT_OFF_PLANES_H_
