// Region dropping decided by the segmentation energy (energy.h): the label
// removal of PEARL (Isack & Boykov, IJCV 2012) with label costs (Delong et
// al., IJCV 2012). A region is dropped, its vertices going to the
// neighbours whose surfaces they fit best and those neighbours refitted, iff
// that lowers E. A fragment grown from rows along a crease or a noisy rim
// lies on its neighbours' surfaces, or on none, and its own surface and
// label cost buy nothing; a face across a crease, however small, lies on no
// neighbour and its vertices would cost c_out there: it stays.
#ifndef MESHSEG_SRC_SEGMENT_DROP_REGIONS_H_
#define MESHSEG_SRC_SEGMENT_DROP_REGIONS_H_

#include <vector>

#include "absl/status/statusor.h"
#include "segment/kept_prices.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Repeatedly drops the alive region whose DropDelta (each region priced
// re-estimated, energy.h) is the most negative, giving its vertices the
// labels that move gives them and its takers the move's refitted surfaces;
// stops when no drop lowers E. Dropped regions get alive = false and no
// vertices. `prices` (may be null) keeps prices for the next step.
// Returns the number of drops. Errors: CANCELLED on stop.
absl::StatusOr<int> DropRegions(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions,
                                KeptPrices* prices = nullptr);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_DROP_REGIONS_H_
