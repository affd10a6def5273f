// Boundary refinement (our addition to ALGORITHMS.md S1 and S2): region
// growing takes every vertex that meets (5) and (6), so where a plane runs
// tangent into a fillet the plane, grown first, keeps the fillet's first
// th_nm degrees of arc. At sigma = 0.15 h (th_nm ≈ 11°) that was 13–28 % of a
// radius-10 h fillet. Here each non-sharp boundary vertex goes to whichever
// neighbouring region's surface it matches best, distance and normal
// together, and the regions are refitted.
#ifndef MESHSEG_SRC_SEGMENT_REFINE_BOUNDARIES_H_
#define MESHSEG_SRC_SEGMENT_REFINE_BOUNDARIES_H_

#include <vector>

#include "absl/status/status.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Sweeps per round (each moves a boundary by at most one edge) and rounds
// of sweeps followed by a refit of the regions that changed.
inline constexpr int kMaxBoundarySweeps = 10;
inline constexpr int kBoundaryRounds = 2;

// How badly vertex v matches the surface it projects onto as `pr`:
// (d / th_dis)² + (θ / th_nm)², with d its distance to the surface and θ the
// angle between n'_v and the surface normal at the closest point.
double MismatchScore(const SegmentContext& c, int v, const Projection& pr);

// Moves non-sharp vertices to the neighbouring region (a region one of their
// edges leads to) with the lowest MismatchScore, if they meet (5) and (6)
// for it and score lower there than in their own region. Sweeps update all
// vertices at once (the result does not depend on the order or the thread
// count); a vertex only ever moves to a lower score, so the sweeps end.
// Updates the regions' vertex lists and surfaces. Errors: CANCELLED on stop.
absl::Status RefineBoundaries(const SegmentContext& c, std::vector<int>* labels,
                              std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_REFINE_BOUNDARIES_H_
