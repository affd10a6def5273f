// Face labels of ALGORITHMS.md S2 (faces and boundaries): a face whose three
// vertex labels agree takes that label; otherwise the label of the vertex
// region whose surface normal (at the face centroid) is closest to the face
// normal. Then small disconnected pieces of a region go to the region around
// them (our addition).
#ifndef MESHSEG_SRC_SEGMENT_FACE_LABELS_H_
#define MESHSEG_SRC_SEGMENT_FACE_LABELS_H_

#include <vector>

#include "meshseg/mesh.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Returns one label per face of `mesh` (-1 if no vertex has a label), with
// MergeFaceFragments applied.
std::vector<int> FaceLabels(const SegmentContext& c, const TriMesh& mesh,
                            const std::vector<int>& labels,
                            const std::vector<RegionState>& regions);

// Where two surfaces meet tangentially (a fillet and its face) both fit the
// faces along the junction, and the noise labels them: on a plate with a
// standing cylinder, its torus fillet and torus edge round, at sigma = 0.05 h,
// the boundaries came out as 199 curves in 114 loops, most around pieces of
// 1-6 faces cut off their regions (without them 20 curves and 22 loops, as on
// the noise-free mesh). Every edge-connected piece of a label that is not the
// label's largest and has fewer than kMaxFragmentFaces faces takes the label
// it shares the most edges with, counting only pieces that are not fragments
// themselves (ties: the lower label); repeated, at most kMaxFragmentRounds
// times, while pieces change. Faces labelled -1 are left alone and never
// given.
void MergeFaceFragments(const TriMesh& mesh, std::vector<int>* face_labels);
inline constexpr std::size_t kMaxFragmentFaces = 60;  // kMinRegionVertices, in faces
inline constexpr int kMaxFragmentRounds = 8;

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FACE_LABELS_H_
