#include "pipeline/memory_model.h"

#include <algorithm>
#include <array>
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
  if (params.include_mesh) {
    bytes += static_cast<double>(kBytesPerReturnedFace) *
             static_cast<double>(input.point_cloud ? input.vertex_count : CostedFaces(input));
  }
  bytes *= kSafetyMargin;
  constexpr double kMax = static_cast<double>(std::numeric_limits<int64_t>::max());
  return bytes >= kMax ? std::numeric_limits<int64_t>::max()
                       : static_cast<int64_t>(std::ceil(bytes));
}

InputSize VolumeInputSize(const VolumeInfo& info, const PipelineParams& params,
                          int64_t file_bytes, int64_t* extra_bytes) {
  const std::array<int64_t, 3>& d = info.geometry.dims;
  // In double: the dims are bounded by max_voxels, but their products are not
  // checked here.
  const double box = static_cast<double>(d[0]) * d[1] + static_cast<double>(d[1]) * d[2] +
                     static_cast<double>(d[0]) * d[2];
  const double faces = std::min(kVolumeFacesPerBoxFace * box, 1e18);
  InputSize input;
  input.format = info.format;
  input.face_count = static_cast<int64_t>(faces);
  input.vertex_count = input.face_count / 2;
  input.file_bytes = file_bytes;
  double extra = static_cast<double>(kBytesPerSliceVoxel) * d[0] * d[1];
  const VolumeMode mode = params.volume.mode;
  const bool maybe_binary = mode == VolumeMode::kBinary ||
                            (mode == VolumeMode::kAuto && info.type == VoxelType::kUint8);
  if (maybe_binary) extra += static_cast<double>(kBinaryBytesPerVoxel) * info.geometry.VoxelCount();
  *extra_bytes = static_cast<int64_t>(std::min(extra, 1e18));
  return input;
}

}  // namespace meshseg::pipeline_internal
