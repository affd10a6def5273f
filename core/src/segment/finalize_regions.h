// The stage's output: final refit of every region, face labels, regions
// renumbered 0..n-1 in order of their first face, and per-region counts,
// area and geometric rms / max distance of the region's vertices.
#ifndef MESHSEG_SRC_SEGMENT_FINALIZE_REGIONS_H_
#define MESHSEG_SRC_SEGMENT_FINALIZE_REGIONS_H_

#include <vector>

#include "meshseg/segment.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Returns the segmentation (estimates left empty) of `mesh` labelled `labels`
// with `regions`. Regions without faces are dropped; their vertices take the
// label of an incident face. Each region's surface is refitted on the vertices
// that meet (5) and (6) for it, while they are at least half of it (a region
// whose type has no valid fit there first takes the TypeThatFitsInstead,
// decide_type.h, if any), and a curved region whose surface is then NearlyFlat
// over it becomes a plane (refitted the same way); then a cylinder between
// two planes is fitted tangent to them (tangent_rounds.h), and the regions of
// one turned feature are fitted to one axis, the pieces of one cylinder
// among them merged (align_coaxial.h). A region's errors are measured over
// all its vertices.
Segmentation FinalizeRegions(const SegmentContext& c, const TriMesh& mesh, std::vector<int> labels,
                             std::vector<RegionState> regions);

// The same for regions decided face by face (exact_facets.h): one label per
// face, the regions' surfaces kept as they are, each vertex labelled with
// an incident face's region.
Segmentation FinalizeFaceRegions(const SegmentContext& c, const TriMesh& mesh,
                                 const std::vector<int>& face_labels,
                                 const std::vector<RegionState>& regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FINALIZE_REGIONS_H_
