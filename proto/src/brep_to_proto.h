// The `brep` stage's report into the public result message.
#ifndef MESHSEG_PROTO_SRC_BREP_TO_PROTO_H_
#define MESHSEG_PROTO_SRC_BREP_TO_PROTO_H_

#include "meshseg/pipeline.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Sets out->brep when `result` carries a STEP export (its report or error).
void SetBrep(const PipelineResult& result, v1::SegmentationResult* out);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SRC_BREP_TO_PROTO_H_
