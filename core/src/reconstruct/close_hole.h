// Closing one hole of the surface left by the support step (issue 38;
// close_unsupported.h): CGAL's triangulation, refinement and fairing of the
// hole (Liepa 2003), a loop too long for its cubic search split by a chord
// first, the patch bent onto the seen planes (seen_planes.h), and flat patch
// triangles flipped away.
#ifndef MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_
#define MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_

#include <cstddef>
#include <vector>

#include <Eigen/Core>

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

// The membrane of a hole (Liepa 2003, harmonic fairing, C0) lies in the
// convex hull of its loop: each coordinate of a harmonic function lies
// between its least and greatest value on the border (maximum principle), so
// every free vertex lies in the loop's bounding box, and the bend onto the
// seen planes (seen_planes.h) moves it by at most the depth of the loop's
// deepest vertex below the cap plane. The cotangent weights CGAL fairs with
// turn negative on obtuse triangles, and on a long, thin refined patch the
// solve can leave the box by far more than the loop's size. Where a patch
// vertex in `vertices` lies more than a mean edge of `loop` (the border
// vertices of its hole, or of the hole it is part of) outside the loop's
// box, the patch is faired again with the umbrella weights (every neighbour
// 1): positive weights, so the maximum principle holds and it stays inside.
void KeepMembraneInsideItsLoop(const std::vector<Eigen::Vector3d>& loop,
                               const std::vector<HoleMesh::Vertex_index>& vertices, HoleMesh* sm);

// A patch triangle on three (nearly) collinear vertices (loop vertices the
// refinement put on one straight crease line) has no area: mesh readers drop
// it, and the surface read back is open. Flips the longest edge of each such
// face of `sm` flagged in "f:filled", when a face lies across it,
// replacing it by two triangles with the apex of that face; the apex lies on
// that edge, so they cover the face across exactly, whether it is a patch face
// or a kept one. Where that edge exists already, the longest edge's end of
// valence 3 is removed (close_hole.cc).
void FlipFlatPatchFaces(HoleMesh* sm);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CLOSE_HOLE_H_
