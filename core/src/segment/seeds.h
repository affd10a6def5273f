// Seeds of ALGORITHMS.md S1 step 2.1: vertices ordered by the mean absolute
// deviation d(i) of kappa_max over N(i, W3), and the seed N(i, W4) of
// non-sharp free vertices around the chosen one.
#ifndef MESHSEG_SRC_SEGMENT_SEEDS_H_
#define MESHSEG_SRC_SEGMENT_SEEDS_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

inline constexpr double kW3 = 3.0;      // ALGORITHMS.md S1 step 2.1
inline constexpr double kW4 = 3.0;      // ALGORITHMS.md S1 step 2.1
inline constexpr std::size_t kMinSeed = 10;  // th_seed, ALGORITHMS.md S1 step 2.1

// Returns the non-sharp measured vertices by increasing d(i) (ties by
// index). A seed is evidence of the surface it proposes: one centred on a
// patch that closes an unscanned area (SegmentContext::Measured) proposes
// the patch's fairing, and one on its rim, mostly patch vertices, a quadric
// that grows over whole faces of the part.
std::vector<int> SeedOrder(const SegmentContext& c);

// Returns the free (labels == -1) non-sharp measured vertices of N(i, W4),
// or an empty vector if fewer than kMinSeed.
std::vector<int> CollectSeed(const SegmentContext& c, int i, const std::vector<int>& labels,
                             NeighborhoodScratch* scratch);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_SEEDS_H_
