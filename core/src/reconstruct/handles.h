// Step 9 of the reconstruction (our addition to ALGORITHMS.md S3, issue 38
// item 1): the handles the points do not support are cut and their holes
// closed. A handle is unsupported when it has a non-separating loop shorter
// than π × handle_spacings local spacings s (the circumference of a hole
// handle_spacings × s across): every point of a surface sampled at spacing s
// lies within about s of a sample, so a hole or a tube's waist no wider than
// 2 s looks like the gaps between samples; the points do not show it, and it
// is not a feature of the sampled surface (Guskov & Wood 2001;
// handle_loops.h). A slit between two sheets has a loop long for the hole it
// bounds; loops up to kSlitLoops times that length are cut when the hole
// they go round (the largest ball in their least-area disc, hole_width.h) is
// at most handle_spacings × s across. Where the refined mesh is coarser than
// the points (its edge raised by the face budget, refine.h), s is at least
// the spacing the mesh follows (its edge over refine_edge_length): the
// output resolves no finer hole than that. The strip of faces around each
// such loop is removed and the two holes it leaves closed by minimal patches
// (close_unsupported.h), flagged as filled.
#ifndef MESHSEG_RECONSTRUCT_HANDLES_H_
#define MESHSEG_RECONSTRUCT_HANDLES_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/status.h"
#include "mesh/point_index.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"

namespace meshseg::reconstruct_internal {

// The genus of the faces of `tri` whose `filled` flag (one per face) is 0,
// the seen surface: (2 C − χ − B) / 2 over those faces alone, with C their
// edge-connected pieces and B their border loops. Without one flag per face,
// every face is taken as seen.
int SeenGenus(const TriMesh& tri, const std::vector<uint8_t>& filled);

// Slits are looked for up to this many times the round-hole loop. A slit's
// gap, not its length, is what the points cannot show, and its width is read
// across its least-area disc (hole_width.h), so the length bounds only the
// search's cost (its balls grow with it), not what is cut. The search runs
// to twice the round-hole loop first, and to kSlitLoops times it only when
// that leaves nothing to cut and the genus is not spent: loops are still cut
// shortest first, and the larger balls are paid only where handles are left.
inline constexpr double kSlitLoops = 4.0;

// Rounds of cutting and closing at most, twice as many with the slit
// search: a loop through the strip of a cut waits for the next round, which
// looks near the last round's patches only.
inline constexpr int kHandleRounds = 8;

// The longest loop cut at each vertex of `tri`, model units: π ×
// `handle_spacings` × the local spacing of the input point nearest to it,
// or × `min_spacing` where that is larger.
std::vector<double> MaxHandleLoops(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index, double handle_spacings,
                                   double min_spacing = 0.0);

// Cuts the unsupported handles of `*mesh` (closed, or open with
// params.leave_unsupported_open) as above and closes (or, with
// leave_unsupported_open, leaves open) the holes; `*filled` (one per face)
// is carried over and gains the patches. Adds to stats->handle_cut_count and
// hole_count and sets filled_face_count and filled_area. Errors: those of
// CloseUnsupported.
absl::Status CutUnsupportedHandles(const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index,
                                   const ReconstructParams& params, Mesh* mesh,
                                   std::vector<uint8_t>* filled, ReconstructStats* stats);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_HANDLES_H_
