// Face labels of seed 002: a face whose three vertex labels agree takes that
// label; otherwise the label of the vertex region whose surface normal (at
// the face centroid) is closest to the face normal.
#ifndef MESHSEG_SRC_SEGMENT_FACE_LABELS_H_
#define MESHSEG_SRC_SEGMENT_FACE_LABELS_H_

#include <vector>

#include "meshseg/mesh.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Returns one label per face of `mesh` (-1 if no vertex has a label).
std::vector<int> FaceLabels(const SegmentContext& c, const TriMesh& mesh,
                            const std::vector<int>& labels,
                            const std::vector<RegionState>& regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FACE_LABELS_H_
