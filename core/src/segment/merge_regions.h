// Region merging of seed 000 §4 steps 3 and 4 on the simplified region
// graph: merge by extrapolation (a neighbour whose vertices fit the larger
// region's surface), then by refitting (the pair whose union fits one
// surface best).
#ifndef MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_
#define MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_

#include <vector>

#include "absl/status/status.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

inline constexpr double kBeta1 = 0.9;  // seed 000 §4 step 3
inline constexpr double kBeta2 = 0.9;  // seed 000 §4 step 4

inline constexpr std::size_t kMinRetypeVertices = 10;

// Gives general-quadric regions the first analytic type passing the alpha
// test on their non-sharp vertices (regions change after absorption and
// merging, so seed 000 §3 step 5 is asked again).
void RetypeQuadrics(const SegmentContext& c, std::vector<RegionState>* regions);

// Merges regions in place (merged-away regions get alive = false and no
// vertices): extrapolation, refitting, retyping of quadrics, extrapolation. Errors: CANCELLED on stop.
absl::Status MergeRegions(const SegmentContext& c, std::vector<int>* labels,
                          std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_
