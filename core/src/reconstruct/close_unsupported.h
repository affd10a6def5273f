// Unsupported faces of the reconstructed surface removed, and the holes they
// leave closed by minimal patches (issue 38: "no invented surface"; the faces
// come from support.h). Our addition to the reconstruction method (ALGORITHMS.md S3),
// whose graph cut closes
// every gap of the scan with the zero set of f extrapolated from the nearest
// fits: flaps and tubes (spurious handles) where no point is.
//
// The removed set is first made a union of disks and annuli a manifold can
// lose: a vertex whose fan would alternate between kept and removed faces
// more than once (a pinch) loses all its faces, and kept pieces smaller than
// min_component_fraction of the largest are removed too (filling every loop
// on its own would otherwise seal such an island into a bubble). Each border
// loop is then closed by CGAL's hole filling (Liepa 2003): the minimal-weight
// triangulation of the loop (area, then dihedral angles), refined to the
// density of the loop's edges and faired with harmonic (membrane, continuity
// 0) weights: the least-area smooth patch the loop spans, not an
// extrapolation of the fits. Where the loop climbs the seen walls of a convex
// hole, the membrane cuts their corners with the unseen face; the support
// step then bends it onto the seen surfaces extended (seen_planes.h). A
// removed tube of a handle leaves two loops, each closed by a disk: the
// handle the points did not support is cut; but where the two loops are the
// rims of an unseen ring-shaped surface, the support step joins them by a
// tube (close_tube.h).
#ifndef MESHSEG_RECONSTRUCT_CLOSE_UNSUPPORTED_H_
#define MESHSEG_RECONSTRUCT_CLOSE_UNSUPPORTED_H_

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

struct ClosedSurface {
  Mesh mesh;
  std::vector<uint8_t> filled;     // one per face of `mesh`: 1 = a patch face
  int64_t removed_face_count = 0;  // faces of the input mesh removed
  int64_t hole_count = 0;          // border loops (closed, or left open)
  double filled_area = 0.0;        // of the patch faces, model units²
};

// Removes the faces of the closed manifold `mesh` whose `supported` flag is
// 0 (grown as above) and, unless `leave_open`, closes every hole. The result
// is an oriented manifold; closed unless `leave_open` (then every edge has one
// or two faces). Each hole is closed by close_hole.h: a loop too long for
// CGAL's cubic search is split by a chord first, and one CGAL cannot
// triangulate is closed by a fan around its centroid. `prior_filled` (one per face of `mesh`, or empty) flags faces a
// previous closing made; kept ones stay flagged in `filled` and count in
// `filled_area`. With `bend_onto_seen_planes` each patch over a convex hole
// is bent onto the seen surfaces extended past it (seen_planes.h); a cut
// handle's two discs stay membranes. With `min_tube_rim` >= 0, the two
// loops of a removed annulus that are the rims of one unseen tube, both
// longer than min_tube_rim (model units), are joined by a tube instead
// (close_tube.h). Errors: INTERNAL if the result breaks these invariants.
absl::StatusOr<ClosedSurface> CloseUnsupported(const Mesh& mesh,
                                               const std::vector<uint8_t>& supported,
                                               double min_component_fraction, bool leave_open,
                                               const std::vector<uint8_t>& prior_filled = {},
                                               bool bend_onto_seen_planes = false,
                                               double min_tube_rim = -1.0);

// Total genus of `tri`: (2 C − χ − B) / 2 with C components, χ = V − E + F
// and B border loops (a closed mesh has B = 0).
int Genus(const TriMesh& tri);

// Border loops of `tri` (0 when closed).
int64_t BorderLoopCount(const TriMesh& tri);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CLOSE_UNSUPPORTED_H_
