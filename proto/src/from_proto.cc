#include <cctype>
#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

// Upper limits of the user-facing tolerances; larger values mean a typo.
constexpr double kMaxDistanceTolerance = 100.0;  // x mean edge length
constexpr double kMaxAngleToleranceDeg = 90.0;

absl::Status CheckTolerance(const char* name, double value, double limit) {
  if (!std::isfinite(value) || value <= 0.0 || value > limit) {
    return absl::InvalidArgumentError(absl::StrCat(
        "segment options: ", name, " must be in (0, ", limit, "], got ", value));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<PipelineParams> FromProto(const v1::SegmentOptions& options) {
  PipelineParams params;
  if (options.has_distance_tolerance()) {
    const absl::Status s = CheckTolerance("distance_tolerance", options.distance_tolerance(),
                                          kMaxDistanceTolerance);
    if (!s.ok()) return s;
    params.segment.distance_tolerance = options.distance_tolerance();
  }
  if (options.has_angle_tolerance_deg()) {
    const absl::Status s = CheckTolerance("angle_tolerance_deg", options.angle_tolerance_deg(),
                                          kMaxAngleToleranceDeg);
    if (!s.ok()) return s;
    params.segment.angle_tolerance_deg = options.angle_tolerance_deg();
  }
  if (options.has_iso_value()) {
    if (!std::isfinite(options.iso_value())) {
      return absl::InvalidArgumentError(
          absl::StrCat("segment options: iso_value must be finite, got ", options.iso_value()));
    }
    params.volume.iso = options.iso_value();
  }
  if (options.volume_mode() == "grey") {
    params.volume.mode = VolumeMode::kGrey;
  } else if (options.volume_mode() == "binary") {
    params.volume.mode = VolumeMode::kBinary;
  } else if (!options.volume_mode().empty() && options.volume_mode() != "auto") {
    return absl::InvalidArgumentError(absl::StrCat("segment options: volume_mode \"",
                                                   options.volume_mode().substr(0, 64),
                                                   "\" is not one of auto, grey, binary"));
  }
  return params;
}

absl::StatusOr<std::optional<FileFormat>> FormatFromHint(std::string_view hint) {
  if (hint.empty()) return std::optional<FileFormat>();
  std::string lower(hint);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (FileFormat f : {FileFormat::kStl, FileFormat::kObj, FileFormat::kOff, FileFormat::kPly,
                       FileFormat::kXyz, FileFormat::kPwn, FileFormat::kNrrd, FileFormat::kMha,
                       FileFormat::kMhd, FileFormat::kRaw}) {
    if (lower == FileFormatName(f)) return std::optional<FileFormat>(f);
  }
  return absl::InvalidArgumentError(absl::StrCat(
      "format hint \"", std::string(hint.substr(0, 64)), "\" is not one of stl, obj, off, ply, xyz, pwn, nrrd, mha, mhd, raw"));
}

absl::Status RawLayoutFromProto(const v1::UploadHeader& header, PipelineParams* params) {
  if (header.raw_dims_size() == 0 && header.raw_voxel_type().empty()) return absl::OkStatus();
  MESHSEG_ASSIGN_OR_RETURN(
      const RawVolumeLayout layout,
      RawLayout({header.raw_dims().begin(), header.raw_dims().end()},
                {header.raw_spacing().begin(), header.raw_spacing().end()},
                {header.raw_origin().begin(), header.raw_origin().end()}, header.raw_voxel_type(),
                header.raw_big_endian()));
  params->volume.read.raw = layout;
  return absl::OkStatus();
}

absl::StatusOr<RawVolumeLayout> RawLayout(const std::vector<int64_t>& dims,
                                          const std::vector<double>& spacing,
                                          const std::vector<double>& origin,
                                          const std::string& voxel_type, bool big_endian) {
  RawVolumeLayout layout;
  if (dims.size() != 3) {
    return absl::InvalidArgumentError(absl::StrCat("raw volume: ", dims.size(), " dims given, need 3"));
  }
  if (!spacing.empty() && spacing.size() != 3) {
    return absl::InvalidArgumentError(absl::StrCat("raw volume: ", spacing.size(), " spacings given, need 3"));
  }
  if (!origin.empty() && origin.size() != 3) {
    return absl::InvalidArgumentError(absl::StrCat("raw volume: ", origin.size(), " origin coordinates given, need 3"));
  }
  for (int a = 0; a < 3; ++a) {
    layout.dims[a] = dims[a];
    if (!spacing.empty()) layout.spacing[a] = spacing[a];
    if (!origin.empty()) layout.origin[a] = origin[a];
  }
  bool known = false;
  for (VoxelType t : {VoxelType::kUint8, VoxelType::kUint16, VoxelType::kInt16, VoxelType::kFloat32}) {
    if (voxel_type == VoxelTypeName(t)) layout.type = t, known = true;
  }
  if (!known) {
    return absl::InvalidArgumentError(absl::StrCat("raw volume: voxel type \"", voxel_type.substr(0, 64),
                                                   "\" is not one of uint8, uint16, int16, float32"));
  }
  layout.big_endian = big_endian;
  return layout;
}

}  // namespace meshseg
