// The upload header target: the first message of an Upload stream as the
// server parses and checks it before it receives any file byte.
#include <cmath>
#include <string>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "fuzz/check.h"
#include "fuzz/upload_target.h"
#include "meshseg/proto/convert.h"
#include "meshseg/v1/service.pb.h"
#include "server/receive_upload.h"
#include "server/server_options.h"

namespace meshseg::fuzz {
namespace {

void CheckError(const absl::Status& status, const char* prefix) {
  Check(status.code() == absl::StatusCode::kInvalidArgument ||
            status.code() == absl::StatusCode::kResourceExhausted,
        "upload errors are INVALID_ARGUMENT or RESOURCE_EXHAUSTED", status.ToString());
  const std::string message(status.message());
  Check(absl::StartsWith(message, prefix), "error says what it refused", message);
  // Quoted names and values are cut (128 and 80 bytes), never echoed whole.
  Check(message.size() < 512, "error message is short", message);
}

bool IsHex64(const std::string& text) {
  if (text.size() != 64) return false;
  for (const char c : text) {
    if (!absl::ascii_isxdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

}  // namespace

void FuzzUploadHeader(std::string_view bytes) {
  v1::UploadRequest request;
  if (!request.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) return;
  if (!request.has_header()) return;  // refused before any check: not a header
  const v1::UploadHeader& header = request.header();
  const int64_t max_bytes = server::ServerOptions().max_upload_bytes;

  const absl::Status checked = server::CheckUploadHeader(header, max_bytes);
  if (!checked.ok()) return CheckError(checked, "upload: ");
  Check(!header.file_name().empty(), "accepted header has a file name");
  Check(header.total_size() > 0 && header.total_size() <= max_bytes,
        "accepted header's size is in (0, max_upload_bytes]");
  Check(header.sha256().empty() || IsHex64(header.sha256()), "accepted sha256 is 64 hex digits",
        header.sha256());

  const absl::StatusOr<PipelineParams> params = FromProto(header.options());
  if (!params.ok()) return CheckError(params.status(), "segment options: ");
  const SegmentParams& segment = params->segment;
  if (header.options().has_distance_tolerance()) {
    Check(std::isfinite(segment.distance_tolerance) && segment.distance_tolerance > 0,
          "accepted distance tolerance is finite and positive");
  }
  if (header.options().has_angle_tolerance_deg()) {
    const double angle = segment.angle_tolerance_deg.value_or(-1.0);
    Check(std::isfinite(angle) && angle > 0 && angle <= 90, "accepted angle tolerance is in (0, 90]");
  }

  const absl::StatusOr<std::optional<FileFormat>> format = FormatFromHint(header.format_hint());
  if (!format.ok()) return CheckError(format.status(), "format hint ");
  Check(format->has_value() != header.format_hint().empty(), "an empty hint means detect");
}

}  // namespace meshseg::fuzz
