#include "client/volume_args.h"

#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {
namespace {

absl::StatusOr<std::vector<double>> NumberList(const Args& args, std::string_view flag) {
  std::vector<double> out;
  const std::optional<std::string> value = args.Value(flag);
  if (!value) return out;
  for (absl::string_view part : absl::StrSplit(*value, ',')) {
    double v;
    if (!absl::SimpleAtod(part, &v)) {
      return absl::InvalidArgumentError(absl::StrCat(
          std::string(flag), " \"", *value, "\" is not a comma-separated list of numbers"));
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace

absl::Status VolumeOptionsFromArgs(const Args& args, UploadOptions* options) {
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> iso, args.Double("--iso"));
  if (iso) options->segment.set_iso_value(*iso);
  if (const std::optional<std::string> mode = args.Value("--volume-mode")) {
    options->segment.set_volume_mode(*mode);
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<double> dims, NumberList(args, "--dims"));
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<double> spacing, NumberList(args, "--spacing"));
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<double> origin, NumberList(args, "--origin"));
  const std::optional<std::string> type = args.Value("--type");
  if (dims.empty() && !type) return absl::OkStatus();
  std::vector<int64_t> sizes;
  for (double d : dims) sizes.push_back(static_cast<int64_t>(d));
  // Checked here with the server's own rule, so both paths refuse alike.
  MESHSEG_RETURN_IF_ERROR(
      RawLayout(sizes, spacing, origin, type.value_or(""), args.Has(kBigEndianSwitch)).status());
  v1::UploadHeader& raw = options->raw;
  raw.mutable_raw_dims()->Add(sizes.begin(), sizes.end());
  raw.mutable_raw_spacing()->Add(spacing.begin(), spacing.end());
  raw.mutable_raw_origin()->Add(origin.begin(), origin.end());
  raw.set_raw_voxel_type(type.value_or(""));
  raw.set_raw_big_endian(args.Has(kBigEndianSwitch));
  if (options->format_hint.empty()) options->format_hint = "raw";
  return absl::OkStatus();
}

}  // namespace meshseg::cli
