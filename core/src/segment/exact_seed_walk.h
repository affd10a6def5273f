// The seed walk of the exact-facet path (exact_facets.h): every facet's
// hypotheses, seeded in order and skipping facets a hypothesis already
// holds, computed on every core with the result of the one-by-one walk.
//
// What a seed gives (its plane, and its first curved fit unless that plane
// holds all its smooth neighbours) depends on the seed facet alone; only
// which facets seed depends on the walk before them. So the walk's later
// stretches are walked ahead, on other threads, as if nothing before them
// held their facets, and their seeds' results kept; the walk itself then
// takes a kept result wherever it seeds the same facet, and computes the
// seeds that walking ahead skipped (a facet held there by a hypothesis the
// walk itself never made). Results, and the hypotheses in their order, are
// those of the walk alone; walking ahead only spends idle cores.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_SEED_WALK_H_
#define MESHSEG_SRC_SEGMENT_EXACT_SEED_WALK_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "segment/exact_hypotheses.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// Seeds in order of the sharpest edge around them (the inside of a face
// before its border, where the facets around a seed reach into the next
// face), then by index; each facet no hypothesis holds yet gives its plane
// (PlaneAt) and, unless that plane holds every neighbour across an edge
// flatter than kSeedCreaseDeg, the curved hypothesis around it (CurvedAt).
// Errors: CANCELLED on stop.
absl::StatusOr<std::vector<Hypothesis>> SeedHypotheses(const FacetMesh& fm, double tau,
                                                       const RunContext& ctx);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_SEED_WALK_H_
