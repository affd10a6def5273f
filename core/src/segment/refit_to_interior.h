// The surface a curved region's interior proposes, and the move E makes of
// it (our addition to ALGORITHMS.md S1 and S2; the surface's counterpart of
// retype_by_interior.h, which proposes a type).
// A region's outer row of vertices lies along the boundary it shares with
// its neighbour, where the labelling, not the surface, decided who holds
// them. A region that kept rows of a neighbour's face (a plane split off a
// curved region leaves it the rows along the cut) is refitted to them with
// them: a narrow band of torus, whose radii trade off against each other,
// bends its tube to hold a row of the flat face beside it (a round of
// radius 2 on a rim of radius 10: R 7.05 r 3.23 over all its vertices, R
// 7.99 r 2.01 over its interior). On that surface the rows cost less than
// on the neighbour's, so the expansion keeps them where they are, and the
// re-estimation keeps the bent surface: a fixed point the moves that change
// one thing at a time do not leave. The surface its interior fits is the
// other labelling's surface; E prices it with the expansion it enables.
#ifndef MESHSEG_SRC_SEGMENT_REFIT_TO_INTERIOR_H_
#define MESHSEG_SRC_SEGMENT_REFIT_TO_INTERIOR_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/fit.h"
#include "segment/kept_prices.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// A proposed surface for region `id`, of its own type, fitted free.
struct InteriorSurface {
  int id = -1;
  Surface surface;
};

// The proposals, one per cylinder, sphere, cone or torus region at most: the
// region's own type fitted to its interior vertices (InteriorVertices,
// at least kMinInteriorVertices of them), where that fit meets them at the
// noise (FitsAtNoise) and the region's surface misses them beyond it (its
// model error there over kMinModelError sigmas, ModelErrorOfMeanSquare). A
// region whose type does not fit its interior is the type proposals'
// (retype_by_interior.h); one whose surface meets its interior has nothing
// to gain. Nothing is proposed on a noise-free mesh or one whose vertices
// lie on facets (no noise to fit at). With `kept`, a region that proposed
// nothing and is unchanged since is not asked again (KeptPrices::Refused).
std::vector<InteriorSurface> ProposeInteriorSurfaces(const SegmentContext& c,
                                                     const std::vector<int>& labels,
                                                     const std::vector<RegionState>& regions,
                                                     KeptPrices* kept = nullptr);

// The refit to the interior as a move of E (energy.h): each proposal, in id
// order, made together with the expansion it enables (alpha_expansion.h,
// re-estimation included), and kept iff E falls. The proposed surface is not
// re-estimated before the expansion: refitted to all the region's vertices
// it would be the bent surface again. Priced at an expansion's fixed point
// (as Improve asks it), so that the expansion alone would gain nothing.
// Returns the ids refitted. Errors: CANCELLED on stop.
absl::StatusOr<std::vector<int>> RefitToInterior(const SegmentContext& c,
                                                 std::vector<int>* labels,
                                                 std::vector<RegionState>* regions,
                                                 KeptPrices* kept = nullptr);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_REFIT_TO_INTERIOR_H_
