// Removal of tiny closed components (bubbles) from the reconstructed surface.
// Our addition to seed 001: with a constant k (§4 names it as open) the cut
// keeps bubbles of one or two tet vertices that noise flips near the surface.
#ifndef MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_
#define MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_

#include <cstdint>

#include "reconstruct/marching_tetrahedra.h"

namespace meshseg::reconstruct_internal {

// Removes the connected components of `surface` with fewer triangles than
// `min_fraction` × those of the largest, with their vertices (the rest is
// renumbered in order). Returns the number of components removed. Closed,
// manifold components stay closed and manifold.
int64_t DropSmallComponents(double min_fraction, IsoSurface* surface);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_
