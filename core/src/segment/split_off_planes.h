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
//  3. splits the plane's vertices off as a new plane region if both sides
//     keep kMinRegionVertices, the two meet at a crease (the curved
//     surface's normal along the junction is at least min(th_bnd, 3 th_nm)
//     from the plane's: a fillet's flat-looking rows meet their face
//     tangentially and are the boundary refinement's business), and plane
//     and rest explain the region better than its type alone
//     (InformationScore, by kScoreMargin).
// A quadric region left without the plane gets the curved type that passes
// the alpha test on the rest, if any. Nothing happens when the estimated
// noise is zero. Returns the ids of the regions split (their planes are
// appended to `regions`).
std::vector<int> SplitOffPlanes(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SPLIT_OFF_PLANES_H_
