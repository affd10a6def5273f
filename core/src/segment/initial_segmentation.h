// The initial segmentation of ALGORITHMS.md S1 step 2: seed, grow with the
// height function, accept a plane, else grow with the general quadric and
// decide the type; each accepted type is grown once more with its own
// surface.
#ifndef MESHSEG_SRC_SEGMENT_INITIAL_SEGMENTATION_H_
#define MESHSEG_SRC_SEGMENT_INITIAL_SEGMENTATION_H_

#include <vector>

#include "absl/status/status.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Appends the grown regions to `regions` and labels their vertices in
// `labels` (one per vertex, -1 = free). Errors: CANCELLED on stop.
absl::Status GrowInitialRegions(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions);

// Our addition before S1's loop, run when the mesh has noise: every seed
// (in `order`) that passes the plane test is grown first, and kept if it
// grows to a plane whose interior no curved type explains kScoreMargin
// better (InformationScore). In S1's order alone a fillet's seed can come
// first, and its quadric grows over the flat face it is tangent to before
// any seed there: a convex edge round (r 4 h) along a plane annulus 6 h
// wide took 200 vertices of the annulus at sigma = 0.15 h and ended as a
// compromise torus. This follows S2, which grows its largest labelled seeds
// first (a flat face is one plane seed there). The curved-type check keeps
// a plane out of a torus or a wide cylinder, where a flat-looking seed
// grows a strip that passes the alpha test (a torus of R = 3 r, r 17 h, at
// sigma = 0.05 h). Appends the planes to `regions`.
// Errors: CANCELLED on stop.
absl::Status GrowPlanesFirst(const SegmentContext& c, const std::vector<int>& order,
                             std::vector<int>* labels, std::vector<RegionState>* regions);

// Grows region `id` (already labelled) from its vertices and sets its type
// and surface.
void GrowAndType(const SegmentContext& c, int id, std::vector<int>* labels,
                 std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_INITIAL_SEGMENTATION_H_
