// Regions that lie on one surface: the faces of a B-rep that share their
// geometry (coplanar faces, the two halves of a bore interrupted by a cross
// hole, the patches of a chamfer interrupted by flats). Two analytic regions
// of one type lie on one surface when every corner of each lies within the
// tolerance of the other's surface; the groups so joined (transitively) are
// fitted together on all their corners, and kept together only if that
// joint fit holds every corner within the tolerance.
#ifndef MESHSEG_SRC_SEGMENT_SHARED_SURFACES_H_
#define MESHSEG_SRC_SEGMENT_SHARED_SURFACES_H_

#include <vector>

#include "meshseg/segment.h"
#include "segment/exact_facets.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// Returns the surfaces of `regions` (surfaces in fm's frame; members
// ascending) and sets surface_of_region (one per region; a FREEFORM region
// is a surface of its own).
std::vector<SharedSurface> GroupSharedSurfaces(const FacetMesh& fm,
                                               const std::vector<ExactRegion>& regions, double tau,
                                               std::vector<int>* surface_of_region);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SHARED_SURFACES_H_
