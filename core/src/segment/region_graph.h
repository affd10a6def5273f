// The region graph of seed 000 §4 step 1 and its simplification (step 2):
// regions are adjacent where a mesh edge joins them; an arc is kept only if
// the junction is smooth (mean normals of the two boundary strips within
// th_bnd) and the types agree or one of them is a general quadric.
#ifndef MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_
#define MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

struct RegionArc {
  int a = 0;  // a < b
  int b = 0;
  double angle_deg = 0.0;  // between the mean normals of the boundary strips
  bool smooth = false;     // angle below th_bnd
  bool kept = false;       // smooth and type-compatible
};

inline constexpr double kSharpBoundaryDeg = 45.0;  // th_bnd, seed 000 §4 step 2

// Returns the arcs between alive regions, sorted by (a, b).
std::vector<RegionArc> BuildRegionGraph(const SegmentContext& c, const std::vector<int>& labels,
                                        const std::vector<RegionState>& regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_
