// The initial segmentation of seed 000 §3: seed, grow with the height
// function, accept a plane, else grow with the general quadric and decide
// the type; each accepted type is grown once more with its own surface.
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

// Grows region `id` (already labelled) from its vertices and sets its type
// and surface.
void GrowAndType(const SegmentContext& c, int id, std::vector<int>* labels,
                 std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_INITIAL_SEGMENTATION_H_
