#include "meshseg/proto/result_json.h"

#include <google/protobuf/util/json_util.h>

#include "absl/strings/str_cat.h"

namespace meshseg {

absl::StatusOr<std::string> ResultJson(const v1::SegmentationResult& result) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;    // DESIGN.md: snake_case names
  options.always_print_primitive_fields = true;  // region id 0, zero counts
  options.always_print_enums_as_ints = false;    // enums as names
  options.add_whitespace = false;
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(result, &json, options);
  if (!status.ok()) {
    return absl::InternalError(
        absl::StrCat("result json: printer failed: ", status.ToString()));
  }
  json.push_back('\n');
  return json;
}

absl::StatusOr<v1::SegmentationResult> ParseResultJson(std::string_view json) {
  v1::SegmentationResult result;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = true;  // results of newer versions
  const auto status = google::protobuf::util::JsonStringToMessage(
      google::protobuf::StringPiece(json.data(), json.size()), &result, options);
  if (!status.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("result json: not a segmentation result: ", status.ToString()));
  }
  return result;
}

}  // namespace meshseg
