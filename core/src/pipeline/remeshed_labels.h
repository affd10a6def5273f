// Carries the labels of a remeshed surface back to the mesh it was made from.
#ifndef MESHSEG_PIPELINE_REMESHED_LABELS_H_
#define MESHSEG_PIPELINE_REMESHED_LABELS_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// Returns one label per face of `original`: the majority label of the
// `remeshed` faces nearest to four points of the face (its centroid and the
// midpoints from the centroid to each corner); the centroid's label breaks
// ties. `remeshed_labels` has one entry per face of `remeshed`.
std::vector<int> TransferFaceLabels(const TriMesh& remeshed, std::span<const int> remeshed_labels,
                                    const TriMesh& original);

// Drops the regions no face of `face_labels` carries (small regions of the
// remesh that no input face took), renumbers the rest 0..n-1 in order, and
// sets their face and vertex counts from the labels of the input mesh.
void CompactRegions(std::vector<int>* face_labels, std::vector<int>* vertex_labels,
                    std::vector<Region>* regions);

// Returns one label per vertex of `mesh`: the label most of its faces carry
// (the smallest on ties), -1 for an isolated vertex.
std::vector<int> VertexLabelsFromFaces(const TriMesh& mesh, std::span<const int> face_labels);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_REMESHED_LABELS_H_
