// The random covering of the octree's cube by support balls. Seed 001
// §2.1.2 steps (2)-(3).
#ifndef MESHSEG_RECONSTRUCT_COVER_H_
#define MESHSEG_RECONSTRUCT_COVER_H_

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/local_fit.h"
#include "reconstruct/octree.h"

namespace meshseg::reconstruct_internal {

// Returns supports covering every leaf: in an order drawn from `seed`, each
// leaf centre not yet covered gets a support (FitSupport with the lower bound
// 0.75 × its cell diagonal), which covers the leaves whose 8 corners it
// contains. Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<Support>> CoverBySupports(const std::vector<OctreeLeaf>& leaves,
                                                     const FitInput& in, uint64_t seed,
                                                     const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_COVER_H_
