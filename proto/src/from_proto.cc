#include <cctype>
#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

// The range a wire option must lie in; an open end excludes its bound.
struct Range {
  double lo;
  bool lo_open;
  double hi;
  bool hi_open;
};

// Distance tolerance: a multiple of the mean edge length; over 100 means a
// typo (seed 000 uses 0.5). Angle tolerance: a deviation of the normals, in
// (0, 90) degrees as SegmentParams requires (90 would accept any face).
constexpr Range kDistanceTolerance{0.0, true, 100.0, false};
constexpr Range kAngleToleranceDeg{0.0, true, 90.0, true};
// Control mesh size per region face (#35): SubdivParams::max_face_fraction
// bounds it; more control vertices than a quarter of the data points leave
// too few points per unknown to average the noise out.
constexpr Range kFreeformFaceFraction{0.0, true, 0.25, false};

// Returns OK if `value` lies in `range`; else INVALID_ARGUMENT naming the
// field, its range in interval notation and the value.
absl::Status CheckRange(const char* field, double value, const Range& range) {
  const bool above_lo = range.lo_open ? value > range.lo : value >= range.lo;
  const bool below_hi = range.hi_open ? value < range.hi : value <= range.hi;
  if (std::isfinite(value) && above_lo && below_hi) return absl::OkStatus();
  return absl::InvalidArgumentError(
      absl::StrCat("segment options: ", field, " must be in ", range.lo_open ? "(" : "[", range.lo,
                   ", ", range.hi, range.hi_open ? ")" : "]", ", got ", value));
}

}  // namespace

absl::StatusOr<PipelineParams> FromProto(const v1::SegmentOptions& options) {
  PipelineParams params;
  if (options.has_distance_tolerance()) {
    MESHSEG_RETURN_IF_ERROR(
        CheckRange("distance_tolerance", options.distance_tolerance(), kDistanceTolerance));
    params.segment.distance_tolerance = options.distance_tolerance();
  }
  if (options.has_angle_tolerance_deg()) {
    MESHSEG_RETURN_IF_ERROR(
        CheckRange("angle_tolerance_deg", options.angle_tolerance_deg(), kAngleToleranceDeg));
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
  switch (options.segmentation_path()) {
    case v1::SEGMENTATION_PATH_UNSPECIFIED: break;
    case v1::SEGMENTATION_PATH_EXACT_FACETS: params.segment.exact = ExactMode::kAlways; break;
    case v1::SEGMENTATION_PATH_SCAN: params.segment.exact = ExactMode::kNever; break;
    default:
      return absl::InvalidArgumentError(absl::StrCat(
          "segment options: segmentation_path must be EXACT_FACETS, SCAN or unspecified, got ",
          v1::SegmentationPath_Name(options.segmentation_path())));
  }
  if (options.has_exact_tolerance()) {
    if (!std::isfinite(options.exact_tolerance()) || !(options.exact_tolerance() > 0.0)) {
      return absl::InvalidArgumentError(absl::StrCat(
          "segment options: exact_tolerance must be > 0, got ", options.exact_tolerance()));
    }
    params.segment.exact_tolerance = options.exact_tolerance();
  }
  params.reconstruct.leave_unsupported_open = options.open_unsupported();
  if (options.has_freeform_fit()) params.freeform.enabled = options.freeform_fit();
  if (options.has_freeform_face_fraction()) {
    MESHSEG_RETURN_IF_ERROR(CheckRange("freeform_face_fraction", options.freeform_face_fraction(),
                                       kFreeformFaceFraction));
    params.freeform.subdiv.face_fraction = options.freeform_face_fraction();
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
