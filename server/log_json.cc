#include "server/log_json.h"

#include <array>
#include <cstdint>

#include "absl/strings/str_format.h"
#include "meshseg/proto/utf8.h"

namespace meshseg::server {

std::string JsonString(std::string_view text) {
  std::string out = "\"";
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const auto b = static_cast<uint8_t>(c);
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (b < 0x20 || b == 0x7F) {
      out += absl::StrFormat("\\u%04x", b);
    } else if (const std::size_t n = Utf8SequenceLength(text.substr(i)); n > 0) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    } else {
      out += absl::StrFormat("\\u%04x", b);  // a byte of no well-formed sequence
    }
    ++i;
  }
  out.push_back('"');
  return out;
}

std::string_view LevelOf(std::string_view event) {
  constexpr std::array<std::string_view, 3> kErrors = {
      "job_record_not_written", "job_dropped", "test_abort_on_file"};
  constexpr std::array<std::string_view, 11> kWarnings = {
      "upload_rejected",    "spool_folder_skipped", "store_unavailable_retrying",
      "queue_unavailable",  "redis_unavailable_at_start", "job_reclaimed",
      "shutdown_releasing_running_jobs", "job_gave_up", "metrics_request_refused",
      "tokens_reload_failed", "listen_loopback_only"};
  for (std::string_view e : kErrors) {
    if (e == event) return "error";
  }
  for (std::string_view w : kWarnings) {
    if (w == event) return "warn";
  }
  return "info";
}

}  // namespace meshseg::server
