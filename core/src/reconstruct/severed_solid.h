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
// A vertex the points resolve that the cut turned outside itself (one
// outside the set ResolvedInside ties to the source: it can turn no other)
// is such a piece, of one vertex, and is given back under the same two
// conditions.
// ResolvedInside (graph_cut.h) ties to the source only the largest set of
// resolved vertices joined by tet edges, leaving the cut free to drop a
// ghost sheet's bubble; but where the tets are coarse (under a large flat
// face the balls hide the centres) a vertex well inside a plate, on a
// support holding a hundred points, can have only shallow or sparse tet
// neighbours and so no resolved one: it is then as free as a bubble, and
// the cut turns it outside with the shallow row round it. The tets then
// carve a pocket into the plate under its seen faces, its walls far from
// any point; the support step removes them and the patch that closes the
// unseen face beside it runs up through the plate into the pocket
// (measured on a generated plate 8 thick scanned from above: a vertex
// 1.6 inside its side wall and 5 under its top, 102 points, f = 2.5
// spacings, turned outside; the output's area inside the plate farther
// than 3 spacings from the truth 8.5 % of its area, 3.4 % with it given
// back). A bubble is joined to the solid by no f ≥ 0 (the face's fits read
// f < 0 in front of it), so it stays free.
// `tied` is the set ResolvedInside returned for the cut (the same `f`,
// `sparse` and `epsilon`). `f`, `by_sign`, `sparse`, `seen_outside` (empty:
// none), `tied` and `inside` have one entry per tet vertex.
int64_t RejoinSeveredSolid(const TetMesh& tets, const std::vector<double>& f,
                           const std::vector<uint8_t>& by_sign, const std::vector<uint8_t>& sparse,
                           const std::vector<uint8_t>& seen_outside,
                           const std::vector<uint8_t>& tied, double epsilon,
                           std::vector<uint8_t>* inside);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SEVERED_SOLID_H_
