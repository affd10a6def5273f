// Removal of tiny closed components (bubbles) from the reconstructed surface.
// Our addition to seed 001: with a constant k (§4 names it as open) the cut
// keeps bubbles of one or two tet vertices that noise flips near the surface.
#ifndef MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_
#define MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_

#include <cstdint>

#include "reconstruct/marching_tetrahedra.h"

namespace meshseg::reconstruct_internal {

// Removes the connected components of `surface` with fewer triangles than
// `min_fraction` × those of the largest, and those other than the largest
// whose mean thickness 2 × volume / area is below `min_thickness`, with
// their vertices (the rest is renumbered in order). Returns the number of
// components removed. Closed, manifold components stay closed and manifold.
//
// The thickness test: a closed surface round a volume of thickness t has
// area A ≈ 2 V / t (a slab's two sides). Two sheets nearer than the points
// can resolve are one sheet of points seen as two, the bubble the cut leaves
// round a clump of stray points, not a solid (sampling: a feature needs two
// samples across it). The largest component is the scanned solid: kept.
int64_t DropSmallComponents(double min_fraction, double min_thickness, IsoSurface* surface);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SMALL_COMPONENTS_H_
