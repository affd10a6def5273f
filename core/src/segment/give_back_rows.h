// Giving a region's neighbours back the rows it took from them (our addition
// to ALGORITHMS.md S1 step 3). A curved region can grow over the first rows
// of the faces around it and bend to meet them: a 45-degree countersink band
// between a plane top and a bore, at sigma = 0.15 h, ended as a torus over
// the cone band, 471 faces of the top plane and 370 of the bore, its tube
// bending into both. The boundary refinement leaves such rows where they are,
// since the bent surface meets them as well as the neighbour's does; on the
// interior no type fits at the noise (the torus misses by 0.98 sigma), and
// the type decided there is the one that bends best.
#ifndef MESHSEG_SRC_SEGMENT_GIVE_BACK_ROWS_H_
#define MESHSEG_SRC_SEGMENT_GIVE_BACK_ROWS_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// For every curved or quadric region whose surface, or whose type refitted
// there, does not fit its interior at the noise (FitsAtNoise), each analytic
// neighbour grows back into it from their common boundary over the vertices
// within th_dis of the neighbour's surface (5). The region gives those vertices
// back if the rest, under the best of a plane and the curved types with no more
// parameters than its own (or its quadric), and the rows, under their
// neighbours' surfaces, explain the region's vertices kScoreMargin better than
// its type alone (InformationScore), and the rest keeps kMinRegionVertices; the
// rest takes that type, or its simplest limit (IsLimitOf) that meets the rest
// at the noise (FitsAtNoise). (A more general type for the rest let the
// piece of a cone band beside a small plane disc turn torus and keep the
// disc.) Nothing happens when the estimated noise is zero.
// Returns the ids of the regions that gave rows back.
std::vector<int> GiveBackRows(const SegmentContext& c, std::vector<int>* labels,
                              std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_GIVE_BACK_ROWS_H_
