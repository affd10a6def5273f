// Region merging (ALGORITHMS.md S1 step 3) decided by the segmentation
// energy (energy.h): of the pairs of regions across a smooth arc of the
// region graph, the one whose merge into one refitted surface lowers E
// most is merged, until no merge lowers it. This takes the place of S1's
// merge by extrapolation (beta1, step 3.3) and by refitting (beta2, step
// 3.4) and of the test of two typed pieces against one surface: a merge
// pays, or does not, by the same data, boundary and label costs.
#ifndef MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_
#define MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_

#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Repeatedly merges, the smaller region into the larger, the pair of
// regions across a smooth arc (region_graph.h: the mean normals of the
// boundary strips within th_bnd, a necessary condition for one smooth
// surface) whose MergeDelta over MergeTypes is the most negative, taking
// that move's type and surface; stops when none is negative. Merged-away
// regions get alive = false and no vertices. Returns the number of merges.
// Errors: CANCELLED on stop.
absl::StatusOr<int> MergeRegions(const SegmentContext& c, std::vector<int>* labels,
                                 std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_MERGE_REGIONS_H_
