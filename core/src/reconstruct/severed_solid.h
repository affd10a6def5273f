// Pieces of the solid the graph cut severs from the rest: an addition to
// the graph-cut labelling, so that a solid the implicit function holds
// together is never closed off as a second surface inside it.
#ifndef MESHSEG_RECONSTRUCT_SEVERED_SOLID_H_
#define MESHSEG_RECONSTRUCT_SEVERED_SOLID_H_

#include <cstdint>
#include <vector>

#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

// Rejoins to the main solid (the largest set of inside vertices joined by
// tet edges) each other inside set that the cut severed from it, by giving
// back their sign to the vertices the cut turned outside between them.
// Returns the number of vertices turned back inside.
//
// The cut repairs the sign of f where the points leave it open
// (graph_cut.h); it has no licence to split the solid that f ≥ 0 holds
// together. Its edge weights |f_a + f_b| / |ab| (eq. 10) are smallest
// between two vertices of small f, and just beneath a sampled face f is
// the small depth below it. Where the tets have no vertex deep in the solid
// (the balls there are large and hide the centres), the vertices beneath a
// face join the rest of the solid only through a row of such shallow
// vertices, each tied to the source by k |f| / ave, nearly nothing; their
// other edges run to vertices outside the face, where |f| is large. Turning
// that row outside then costs less than keeping it, and the cut severs the
// piece beneath the face. Marching tetrahedra closes it on itself, and the
// main surface round it; the refinement pulls both onto the face's points,
// and the piece stays a closed second sheet about a spacing beneath the
// wall (or, small, the component drop removes it and leaves a dent).
//
// A severed set is rejoined when both hold:
// - the points resolve its inside on their own: it has a vertex off the
//   hull, of a support holding at least the sparse count of points, with
//   f ≥ `epsilon` (the fit's error; graph_cut.h ResolvedInside). A bubble
//   the cut leaves round noise has none and stays apart, for the
//   small-component drop;
// - f joins it to the main solid: from it, layer by layer over tet edges,
//   through vertices with f ≥ 0 (`by_sign`) that the cut turned outside and
//   that no point sees from outside (`seen_outside`, tied outside by the
//   evidence itself), a layer reaches a vertex of the main solid. Every
//   vertex of the layers up to that one goes back inside: the row the cut
//   turned, not more. A gap whose vertices have f < 0 (two bodies the points
//   show apart) is never crossed.
// `f`, `by_sign`, `sparse`, `seen_outside` (empty: none) and `inside` have
// one entry per tet vertex.
int64_t RejoinSeveredSolid(const TetMesh& tets, const std::vector<double>& f,
                           const std::vector<uint8_t>& by_sign, const std::vector<uint8_t>& sparse,
                           const std::vector<uint8_t>& seen_outside, double epsilon,
                           std::vector<uint8_t>* inside);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SEVERED_SOLID_H_
