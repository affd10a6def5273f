// The split at the cap (issue 38 item 1; a step of close_tube.h): the
// unseen annulus between a bore's rim and the rim round the face it opens
// onto.
//
// Where both rims are seen as straight walls (their curvature across the
// border under half the arcs'), the annulus is split at the face between them
// (ALGORITHMS.md S3): a ruled wall (cylinder, prism) seen down to its rim
// continues straight until it meets the plane of the unseen face. The shorter
// rim is the bore's; its axis is the direction its wall's normals are square
// to. The cap plane is the plane the most of the outer rim lies on, the one a
// disc over the face is bent onto (seen_planes.h SeenCapPlane: consensus,
// then least squares; robust to the rim climbing the walls), within 45° of
// that axis; its normal then gives the axis (the bore runs square to the
// face). The bore's wall runs on straight along the axis to the plane (a
// short tube), and the face is the strip of straight rungs between the outer
// rim and the bore's circle on the plane (a disc with a hole), laid as rings
// a mean edge apart, each as dense as the loops (tube_strip.h), since the
// outer rim's rungs fan in onto the bore's shorter circle. Where the outer
// rim climbs the walls round the face, those rungs cut the corner between
// wall and face as a disc's membrane would, so the strip is bent onto the
// seen planes of the outer rim as a disc is (seen_planes.h). Rim vertices
// stacked along the axis share one foot, so no rung runs along the wall onto
// another's foot (no face without area). When no seen surface ends beyond the
// bore's rim by a mesh edge, there is no cap to reach, and the loops keep
// their discs, bent onto the seen planes (seen_planes.h).
#ifndef MESHSEG_RECONSTRUCT_SPLIT_AT_CAP_H_
#define MESHSEG_RECONSTRUCT_SPLIT_AT_CAP_H_

#include "reconstruct/close_hole.h"
#include "reconstruct/tube_rims.h"

namespace meshseg::reconstruct_internal {

// Closes the annulus between `rim_a` and `rim_b` of `sm` (both as RimOf
// gives them, along their borders; `sign` as for RimOf) by the split above;
// with `bend` the strip across the cap is bent onto the seen planes round
// it. Returns false and leaves `sm` as it was when there is no cap beyond
// the bore's rim (or none square to the bore) or CGAL refuses a face.
bool SplitAtCap(const Rim& rim_a, const Rim& rim_b, double sign, bool bend, HoleMesh* sm);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SPLIT_AT_CAP_H_
