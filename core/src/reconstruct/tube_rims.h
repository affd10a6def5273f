// The rims of an unseen annulus (issue 38 item 1; close_tube.h): which two
// border loops left by the support step are the rims of one unseen tube,
// and how the seen surface leaves each of them.
#ifndef MESHSEG_RECONSTRUCT_TUBE_RIMS_H_
#define MESHSEG_RECONSTRUCT_TUBE_RIMS_H_

#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "reconstruct/close_hole.h"

namespace meshseg::reconstruct_internal {

// A loop's seen surface leaves it out of its plane when the mean |cosine|
// between the outgoing direction and the loop's axis is at least this (45°).
inline constexpr double kMinLeavingCosine = 0.7071;

// A border loop of the seen surface: its vertices in the order of the
// border; at each, the unit direction in which the seen surface leaves it
// (in the tangent plane, across the border, away from the kept faces; they
// lie to the right of the border's direction seen from their front),
// averaged over kDirectionWindow vertices on either side; and the seen
// surface's mean normal curvature across the border (> 0 where it turns
// towards its inside as it goes out, as a torus's section does).
//
// The faces next to the border are the least trustworthy part of the seen
// surface: they reach up to the support step's reach past the last points,
// where the implicit function is extrapolated, and one ring of normals is
// noisier than the turn of a curved section over it. So both come from the
// rings kNearRing and kFarRing edges inside (each rim vertex owns the
// vertices nearest it in edges): the curvature is the turn of the normal
// about the rim's tangent between them over their distance, and the normal
// at the rim is the near ring's turned on by as much as the turn carries on
// to the rim (an arc). A section that curves turns evenly over that reach;
// a crease within it (a countersink's rim above a bore's) turns the normal
// at one place. So the curvature is read over each half of the reach (from
// the near ring to the one halfway and on to the far one), and the slower
// half's rate is taken: a crease in reach reads as no curvature.
struct Rim {
  std::vector<HoleMesh::Vertex_index> loop;
  std::vector<Eigen::Vector3d> out;
  double curvature = 0.0;
};

// The rim of the border loop of `h` of `sm`, as above; `sign` is +1 when the
// faces of `sm` face outwards, else -1.
Rim RimOf(const HoleMesh& sm, HoleMesh::Halfedge_index h, double sign);

// Union-find parents (mesh_internal::FindRoot) of the edge-connected pieces
// of the faces of `tri` whose `removed` flag is `side`.
std::vector<int> FacePieces(const TriMesh& tri, const std::vector<uint8_t>& removed,
                            uint8_t side);

// The pairs (indices into `loops`, border halfedges of `sm`) that are the
// rims of one unseen tube by criteria (a)-(c) of close_tube.h (a removed
// component's other loops, closed as sheets, do not count). `sm` holds
// the faces of `tri` not `removed`; `tri_vertex` maps each vertex of `sm` to
// its vertex of `tri`.
// Only loops longer than `min_rim` (model units) are paired.
std::vector<std::pair<size_t, size_t>> TubeRims(const TriMesh& tri,
                                                const std::vector<uint8_t>& removed,
                                                const HoleMesh& sm,
                                                const std::vector<int>& tri_vertex,
                                                const std::vector<HoleMesh::Halfedge_index>& loops,
                                                double min_rim);

// Pairs (indices into `loops`) of lone rims, each the only candidate rim
// ((b) and (c) of close_tube.h) of its removed component, where the shorter
// one's axis (the normal of its plane) meets the longer one's plane within
// 45° of square and inside it, the shorter one's wall is straight (bent as
// the rim reads it, Rim::curvature, it would turn by less than 45° on its
// run to that plane; a round's section turns on into the unseen part), and
// neither meets nor is met by another lone rim so. The rims of a bore
// whose lower wall and the face it opens onto the scan did not see are the
// bore's rim and the rim round that face: a
// straight wall seen down to its rim continues until it meets the plane of
// the unseen face (split_at_cap.h). Whether the support step leaves them in
// one removed component or two depends on where the implicit function,
// extrapolated through the unseen region, happens to change sign under the
// bore's mouth (the planes of the balls grown under the part read the
// mouth as solid on some coverings and not on others), which is no
// evidence of a floor: none was seen. The caller joins them by the split
// at the cap (split_at_cap.h), which refuses a pair with no cap square to
// the bore beyond its rim. Arguments as for TubeRims.
std::vector<std::pair<size_t, size_t>> LoneBoreRims(
    const TriMesh& tri, const std::vector<uint8_t>& removed, const HoleMesh& sm,
    const std::vector<int>& tri_vertex, const std::vector<HoleMesh::Halfedge_index>& loops,
    double min_rim);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_TUBE_RIMS_H_
