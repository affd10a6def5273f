#include <cctype>
#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/convert.h"

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
  return params;
}

absl::StatusOr<std::optional<FileFormat>> FormatFromHint(std::string_view hint) {
  if (hint.empty()) return std::optional<FileFormat>();
  std::string lower(hint);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (FileFormat f : {FileFormat::kStl, FileFormat::kObj, FileFormat::kOff, FileFormat::kPly,
                       FileFormat::kXyz, FileFormat::kPwn}) {
    if (lower == FileFormatName(f)) return std::optional<FileFormat>(f);
  }
  return absl::InvalidArgumentError(absl::StrCat(
      "format hint \"", std::string(hint.substr(0, 64)), "\" is not one of stl, obj, off, ply, xyz, pwn"));
}

}  // namespace meshseg
