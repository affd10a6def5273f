// Merging pieces of one surface (our addition to ALGORITHMS.md S1 step 3):
// the region graph keeps an arc only between regions of the same type, so
// two pieces of one surface that were typed apart stay apart. At
// sigma = 0.15 h a 45-degree countersink (a cone band 4 h wide between a
// plane top and a bore) can grow from two seeds, one typed a sphere and one
// a cone, and both are right within the tolerances. Whether they are one
// surface is asked of their interiors, where the rows along creases cannot
// bias the fits (retype_by_interior.h).
#ifndef MESHSEG_SRC_SEGMENT_MERGE_SAME_SURFACE_H_
#define MESHSEG_SRC_SEGMENT_MERGE_SAME_SURFACE_H_

#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Repeatedly merges the pair of regions across a smooth arc, both analytic or
// one a general quadric (not two quadrics: the refit merge takes those), that
// one surface explains as well as two, at the noise, or clearly better. First,
// a plane part whose principal curvatures are a curved face's (CurvedField)
// joins its curved neighbour if that type meets the union at the noise or as
// closely as the plane meets the part. On the union's interior vertices, each
// member's part fitted with its own type (or, if that fit fails, taken under
// its region's surface) is scored against one fit of each analytic type to all
// of it (InformationScore, parameters counted for both members); else the pair
// merges if one type meets the union near the noise (kScoredNearError) and two
// surfaces do not score kScoreMargin less, or if it meets the union at the
// noise (FitsAtNoise) and its rms exceeds theirs by at most kScoredNearError
// sigmas (in quadrature: the scores, which grow with the vertex count, then
// count the meshing's bias), or if one type scores kScoreMargin less and meets
// the union at least as closely as the closer part's own fit meets that part,
// or, within kScoredNearError sigmas, as the farther part's does (model
// errors), taking that type (or its simplest limit, IsLimitOf, if that gains
// within kScoreMargin as much), largest gain first. The first and last clauses
// join two plane strips along a round (a 60-degree round of r 4 between two
// planes at sigma = 0.15 h: the cylinder 0.27 sigma off the union, the planes
// 0.17 and 0.35 off theirs, 8.0 better; with other noise, 0.28, 0.34 and
// 0.47, better by more than kScoreMargin). Both parts need
// kMinInteriorVertices. Does nothing when the estimated noise is zero
// (noise-free meshes have no scale for the scores). Returns the number of
// merges.
// Errors: CANCELLED on stop.
absl::StatusOr<int> MergeSameSurface(const SegmentContext& c, std::vector<int>* labels,
                                     std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_MERGE_SAME_SURFACE_H_
