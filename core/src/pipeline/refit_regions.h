// Refits the regions of a remeshed CAD tessellation on the input's own
// vertices.
#ifndef MESHSEG_PIPELINE_REFIT_REGIONS_H_
#define MESHSEG_PIPELINE_REFIT_REGIONS_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// The remesh's vertices lie on the input's flat facets, a chord's sagitta
// inside a coarsely tessellated cylinder; the vertices of a CAD export lie on
// the CAD surface itself. For every region this refits its surface (same
// type, initial normals from the current surface) to the vertices of the
// input faces labelled with it, and keeps the refit where it is closer to
// those vertices than the current surface. rms/max distances are then those
// of the input vertices. `face_labels` has one entry per face of `mesh`.
void RefitOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                          std::vector<Region>* regions);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_REFIT_REGIONS_H_
