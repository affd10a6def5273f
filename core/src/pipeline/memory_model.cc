#include "pipeline/memory_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshseg::pipeline_internal {

int64_t CostedFaces(const InputSize& input) {
  if (input.format == FileFormat::kStl) return input.face_count;
  return std::max(input.face_count, 2 * input.vertex_count);
}

int64_t PeakBytes(const InputSize& input, const PipelineParams& params) {
  // In double: a lying header may declare counts whose bytes overflow int64.
  double bytes = static_cast<double>(kBaseBytes) + static_cast<double>(input.file_bytes);
  if (input.point_cloud) {
    bytes += static_cast<double>(kBytesPerPoint) * static_cast<double>(input.vertex_count);
  } else {
    bytes += static_cast<double>(kBytesPerMeshFace) * static_cast<double>(CostedFaces(input));
    if (params.remesh.mode != RemeshMode::kNever) {
      bytes += static_cast<double>(kBytesPerRemeshFace) *
               static_cast<double>(std::max<int64_t>(params.remesh.max_faces, 0));
    }
  }
  bytes *= kSafetyMargin;
  constexpr double kMax = static_cast<double>(std::numeric_limits<int64_t>::max());
  return bytes >= kMax ? std::numeric_limits<int64_t>::max()
                       : static_cast<int64_t>(std::ceil(bytes));
}

}  // namespace meshseg::pipeline_internal
