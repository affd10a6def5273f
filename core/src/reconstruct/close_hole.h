// Closing one hole of the surface left by the support step (issue 38;
// close_unsupported.h): CGAL's triangulation, refinement and fairing of the
// hole (Liepa 2003), a loop too long for its cubic search split by a chord
// first, the patch bent onto the seen planes (seen_planes.h), and flat patch
// triangles flipped away.
#ifndef MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_
#define MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_

#include <cstddef>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace meshseg::reconstruct_internal {

using HoleKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using HoleMesh = CGAL::Surface_mesh<HoleKernel::Point_3>;

// Closes the hole of border halfedge `h` of `sm` (a loop of `n` vertices):
// CGAL's triangulation, refinement and fairing, or a fan when that fails. A
// loop longer than the cubic search takes is first split by a chord between
// the two loop vertices nearest each other among those a third of the loop
// apart, and each half is closed in turn. With `bend`, each patch is bent
// onto the seen planes of the whole loop; `sign` is +1 when the faces of `sm`
// face outwards, else -1. New faces get the "f:filled" property's default.
void CloseHole(HoleMesh::Halfedge_index h, size_t n, double sign, bool bend, HoleMesh* sm);

// A patch triangle on three (nearly) collinear vertices (loop vertices the
// refinement put on one straight crease line) has no area: mesh readers drop
// it, and the surface read back is open. Flips the longest edge of each such
// face of `sm` flagged in "f:filled", when a patch face lies across it,
// replacing it by two triangles with the apex of that face.
void FlipFlatPatchFaces(HoleMesh* sm);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_
