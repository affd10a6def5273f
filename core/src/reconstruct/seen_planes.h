// The patch over an unseen region bent onto the seen surfaces extended past
// their border (issue 38 item 1; a step of close_unsupported.h).
//
// The membrane that closes a hole (harmonic fairing, Liepa 2003) is the
// unseen surface only where that surface is the plane of a flat loop. The
// unseen side of a scanned solid is bounded by the seen surfaces around the
// hole, and where the hole is convex (a face the part stood on, the far side
// of a convex edge) the solid there is the intersection of their half-spaces.
// So when the seen surfaces stop at different heights above the unseen face,
// the loop climbs the walls, and the membrane spanning it cuts the corner
// between each wall and the unseen face, as a chord cuts a convex edge.
//
// The hull: the tangent plane of the seen surface at every loop vertex (the
// kept faces' area-weighted normal) and the cap plane, the unseen face's
// own. The seen surfaces end at it where they were seen all the way down, so
// it is the plane the most loop vertices lie on, of those within 45° of the
// patch's mean normal that leave the loop on their inner side (a consensus
// over planes through three loop vertices, then least squares; the mean
// normal alone tilts when the loop climbs one wall more than another). Each
// free vertex of the patch inside the hull goes to the nearest point of its
// boundary, i.e. onto the plane with the least clearance. Near a wall that is the wall
// extended, in the middle the cap plane; their intersection is the edge the
// scan did not see. A tangent plane that cuts off part of the loop is no
// face of the hull (a fold of the seen surface at the border) and is left out.
//
// The hull is right only for a convex hole. Around a concave one (a bore, an
// inner corner) most tangent planes cut off part of the loop, and a membrane
// over a saddle lies outside the hull; there the patch is left as it is.
#ifndef MESHSEG_RECONSTRUCT_SEEN_PLANES_H_
#define MESHSEG_RECONSTRUCT_SEEN_PLANES_H_

#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// Largest fraction of a patch's free vertices allowed outside the hull (by
// more than two mean edge lengths of the loop) for the hull to be taken.
inline constexpr double kMaxOutsideFraction = 0.02;
// Largest fraction of the loop's tangent planes that may cut off more than
// kMaxOutsideFraction of the loop (folds at the border) for the hull to be
// taken; around a concave hole nearly all of them do.
inline constexpr double kMaxCuttingFraction = 0.5;

// `loop` (the border vertices of a hole, in order) with `normals` (unit,
// outward, of the seen surface at each), `patch_normal` (the area-weighted
// outward normal sum of the patch's faces) and the patch's free vertices in
// `*free_vertices`. Moves them onto the hull as above and returns true, or
// leaves them and returns false when the hole is not convex (as above), no
// cap plane is found, or the loop is degenerate.
bool BendOntoSeenPlanes(const std::vector<Eigen::Vector3d>& loop,
                        const std::vector<Eigen::Vector3d>& normals,
                        const Eigen::Vector3d& patch_normal,
                        std::vector<Eigen::Vector3d>* free_vertices);

// The length of the closed polygon `loop` (its last vertex joined to its
// first); over loop.size(), the loop's mean edge, the unit the hole steps
// measure their bands and slack in.
double LoopPerimeter(const std::vector<Eigen::Vector3d>& loop);

// The cap plane of `loop` as BendOntoSeenPlanes finds it (the consensus
// plane above, its unit normal within 45° of `mean_normal` and facing the
// same way, and its offset along it). False when there is none.
bool SeenCapPlane(const std::vector<Eigen::Vector3d>& loop, const Eigen::Vector3d& mean_normal,
                  Eigen::Vector3d* normal, double* offset);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SEEN_PLANES_H_
