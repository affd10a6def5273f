// Leftover absorption of ALGORITHMS.md S2 (STB3): free vertices (mostly
// near sharp edges) join a neighbouring region whose surface they meet with
// thresholds stepped up from the base ones; what is still free then joins
// its nearest labelled neighbour, and free islands without any region become
// regions.
#ifndef MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_
#define MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_

#include <vector>

#include "absl/status/status.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Small general-quadric regions are mostly strips grown from seeds next to
// sharp edges; they are released (labels -1, alive = false) before
// absorption so the surfaces on either side take their vertices.
inline constexpr std::size_t kMinQuadricVertices = 60;
inline constexpr double kMinQuadricShare = 0.002;  // of all vertices
void ReleaseSmallQuadrics(const SegmentContext& c, std::vector<int>* labels,
                          std::vector<RegionState>* regions);

// The size under which a region is a fragment to the steps that split,
// give back or snap rows (about 120 faces, below the 200-face primitives
// the segmentation must find); whether a region stays is the energy's
// decision (drop_regions.h).
inline constexpr std::size_t kMinRegionVertices = kMinQuadricVertices;

// Labels every vertex that has a face (labels[v] >= 0 afterwards) and
// updates the regions' vertex lists. Errors: CANCELLED on stop.
absl::Status AbsorbLeftovers(const SegmentContext& c, std::vector<int>* labels,
                             std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_
