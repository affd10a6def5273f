// Loop subdivision surfaces of freeform regions (PipelineResult::subdivisions,
// #35) to and from the result message (v1::Region.subdivision).
#ifndef MESHSEG_PROTO_SRC_SUBDIVISION_PROTO_H_
#define MESHSEG_PROTO_SRC_SUBDIVISION_PROTO_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/pipeline.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Sets Region.subdivision of each region of `out` that `subdivisions` name.
void SetSubdivisions(const std::vector<RegionSubdivision>& subdivisions,
                     v1::SegmentationResult* out);

// Returns the subdivision surfaces of `result`'s regions, by ascending
// region id. Errors (INVALID_ARGUMENT, naming the region, the array and the
// bad value): an array whose length is not a multiple of 3 (vertices,
// faces) or 2 (creases), a vertex id outside the control vertices, a
// non-finite coordinate.
absl::StatusOr<std::vector<RegionSubdivision>> SubdivisionsFromProto(
    const v1::SegmentationResult& result);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SRC_SUBDIVISION_PROTO_H_
