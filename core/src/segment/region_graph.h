// The region graph of ALGORITHMS.md S1 step 3.1 and its simplification
// (step 3.2): regions are adjacent where a mesh edge joins them; an arc is
// smooth if the mean normals of the two boundary strips are within th_bnd.
// (Whether the types agree no longer matters: the energy of a merge decides
// it, merge_regions.h.)
#ifndef MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_
#define MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_

#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

struct RegionArc {
  int a = 0;  // a < b
  int b = 0;
  double angle_deg = 0.0;  // between the mean normals of the boundary strips
  bool smooth = false;     // angle below th_bnd
};

inline constexpr double kSharpBoundaryDeg = 45.0;  // th_bnd, ALGORITHMS.md S1 step 3.2

// Returns the arcs between alive regions, sorted by (a, b).
std::vector<RegionArc> BuildRegionGraph(const SegmentContext& c, const std::vector<int>& labels,
                                        const std::vector<RegionState>& regions);

// A merge of an arc's two regions that a merge step accepts: its score
// (the highest is merged first) and the merged region's type and surface.
struct PairMerge {
  double score = 0.0;
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
};

// The loop of ALGORITHMS.md S1 step 3.4 (MergeRegions): repeatedly merges,
// the smaller region into the larger, the pair across an arc that
// `eligible` admits with the highest score `test(a, b)` gives (nullopt: not
// to be merged), until none is left. Tests are cached per arc and redone
// only for pairs a merge changed; before each round of tests, `prepare`
// (may be empty) is given the pairs about to be tested, (a, b) in arc
// order, so that their prices can be made together. Returns the number of
// merges. Errors: CANCELLED on stop.
absl::StatusOr<int> MergeBestPairs(
    const SegmentContext& c, std::vector<int>* labels, std::vector<RegionState>* regions,
    const std::function<bool(const RegionArc&)>& eligible,
    const std::function<std::optional<PairMerge>(int a, int b)>& test,
    const std::function<void(std::span<const std::pair<int, int>>)>& prepare = {});

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_REGION_GRAPH_H_
