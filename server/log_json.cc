#include "server/log_json.h"

#include <array>
#include <cstdint>

#include "absl/strings/str_format.h"

namespace meshseg::server {
namespace {

// Length of the well-formed UTF-8 sequence at the start of `s`, or 0.
std::size_t Utf8SequenceLength(std::string_view s) {
  const auto byte = [&](std::size_t i) { return static_cast<uint8_t>(s[i]); };
  const uint8_t b0 = byte(0);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  uint8_t lo = 0x80, hi = 0xBF;  // range of the second byte (table 3-7)
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;
    if (b0 == 0xED) hi = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;
    if (b0 == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (s.size() < n || byte(1) < lo || byte(1) > hi) return 0;
  for (std::size_t i = 2; i < n; ++i) {
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  }
  return n;
}

}  // namespace

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
