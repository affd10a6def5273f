// An unseen annulus closed by a tube between its two rims (issue 38 item 1;
// a step of close_unsupported.h).
//
// Where the unseen part of a scanned solid is ring-shaped (the underside of
// a torus between its outer and inner rim; the inside of a bore together
// with the face it opens onto), the support step removes an annulus and
// leaves two border loops. Closing each by its own disc spans the ring's
// hole (the outer disc) and the bore's mouth, far from the surface the scan
// did not see; the surface there is a tube joining the two rims.
//
// Two loops are taken as the rims of one unseen tube when (b) both are
// longer than the loops the points resolve as holes (handles.h: a shorter one
// is a handle the points do not show, which the handle step cuts), (c) at
// both, the seen surface leaves the loop out of its plane: its outgoing
// direction (in the tangent plane, across the border, away from the seen
// faces) runs along the loop's axis, so the seen surface extended is a wall
// leaving the loop, not a sheet closing it, and (a) they are the only loops
// of one removed component that pass (b) and (c) (the implicit function
// joined them through the unseen region; a handle inside it is as
// unsupported as the rest of it and goes with it). A spurious bridge between
// two sheets fails (c): each sheet, extended, closes its own loop as a disc.
// So does a hole in a seen sheet through which the removed component opens
// onto it (the implicit function dug under a seen face, into the unseen
// region behind it): the sheet closes it by its own disc whatever lies
// behind, so it is not counted against (a). Counted, it left the rims of an
// unseen bore's tube to two discs, one across the bore.
//
// The tube is then built (below) and kept only if (d) its arcs bend as the
// seen surface does at each rim: unless the arcs are straight within the
// resolution of a curvature (their mean depth below their chords at most the
// loops' mean edge length), each rim's curvature across the border (read from
// the normals 3, 6 and 9 edges inside, tube_rims.h) is within half of the
// arcs' mean curvature. A torus's section curves on into the unseen side at
// the curvature it had where it was seen. Walls that run straight to the rims
// (a bore and the walls around the face it opens onto) meet the unseen face
// at edges, not in an arc.
//
// Where both rims are seen as straight walls, the annulus is split at the
// face between them instead (split_at_cap.h).
//
// The tube: the loops are joined by a strip of rungs, the sequence of
// loop-vertex pairs of least total rung length (the optimal strip between two
// contours, Fuchs, Kedem & Uselton 1977, with rung length as the cost,
// Christiansen & Sederberg 1978). Along each rung the tube follows the cubic
// Hermite curve that leaves each rim along the seen surface's outgoing
// direction, with the tangent length of the circular arc through both ends
// that turns by the angle between the two directions (a semicircle across a
// torus's tube; a straight line between aligned walls): the seen surfaces
// extended, joined with the continuity of their tangent planes. The tube is
// laid as rings across the rungs a mean loop edge apart along the longest
// arc, each as dense as the loops (tube_strip.h): rows along the rungs would
// crowd where the longer rim's rungs fan in onto the shorter one.
#ifndef MESHSEG_RECONSTRUCT_CLOSE_TUBE_H_
#define MESHSEG_RECONSTRUCT_CLOSE_TUBE_H_

#include "reconstruct/close_hole.h"

namespace meshseg::reconstruct_internal {

// Closes the annulus between the border loops of `a` and `b` of `sm` by the
// tube above (`sign` as for RimOf, tube_rims.h); new faces get the
// "f:filled" property's default; straight walls are split at the cap as
// above, and with `bend` the strip across the cap is bent onto the seen
// planes round it (seen_planes.h), as a hole's patch is. Returns false and
// leaves `sm` as it was when the arcs do not bend as the seen surface does
// at each rim (d) and there is no cap to split at, or the strip cannot be
// added (too long loops).
bool CloseTube(HoleMesh::Halfedge_index a, HoleMesh::Halfedge_index b, double sign, bool bend,
               HoleMesh* sm);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CLOSE_TUBE_H_
