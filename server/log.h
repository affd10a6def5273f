// File: log.h
// -----------------------------------------------------------------------------
// Structured log lines on stderr, one line per call, in one of two formats
// (SetLogFormat, flag --log-format):
//   text (default): `ts=<RFC3339> event=<name> key=value ...`, values quoted
//     when they hold spaces or quotes;
//   json: one JSON object per line, always with "time", "level", "event",
//     "job_id", "tenant", "stage" and "duration" (seconds, null when the event
//     has none), then the other fields as strings.
//
// No secret can reach a log line by construction: an event name and every
// field key are string literals checked at compile time (a key must be one
// of kLogKeys: there is no field for metadata, headers or tokens, and a call
// with another key does not compile), and every value passes through a
// redactor that blanks "Bearer <token>" and any secret registered with
// RegisterLogSecret (the server registers the tokens it loads).
#ifndef MESHSEG_SERVER_LOG_H_
#define MESHSEG_SERVER_LOG_H_

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"

namespace meshseg::server {

// Every field key a log line may carry. Add a key here only for a value that
// can never hold a credential (no request metadata, headers or tokens).
inline constexpr std::array<std::string_view, 55> kLogKeys = {
    "job", "tenant", "stage", "seconds", "state", "error", "code", "reason", "was",
    "file", "input", "folder", "bytes", "result_bytes", "faces", "regions", "attempt",
    "attempts", "peer", "listen", "port", "address", "role", "queue", "queue_capacity",
    "workers", "spool", "grace", "signal", "call", "entry", "idle_over", "redis",
    "requeued", "interrupted", "served", "expired", "cpu_source", "cpu_quota_cores",
    "affinity_cores", "memory_limit_bytes", "metrics", "format", "count", "limit", "version",
    // Security and admission: modes, counts and byte sizes, never a token.
    "transport", "access", "reflection", "request_id", "memory_budget",
    "max_concurrent_streams", "estimate", "reserved", "budget"};

constexpr bool IsLogKey(std::string_view key) {
  for (std::string_view allowed : kLogKeys) {
    if (allowed == key) return true;
  }
  return false;
}

// Deliberately not constexpr: a compile-time LogKey or LogEvent that calls
// it fails to compile, naming it.
void NotAnAllowedLogKey();
void NotALogEventName();

// A field key: a string literal from kLogKeys, checked at compile time.
class LogKey {
 public:
  template <std::size_t N>
  consteval LogKey(const char (&key)[N]) : key_(key, N - 1) {  // NOLINT: implicit on purpose
    if (!IsLogKey(key_)) NotAnAllowedLogKey();
  }
  constexpr std::string_view view() const { return key_; }

 private:
  std::string_view key_;
};

// An event name: a string literal of [a-z0-9_], checked at compile time.
class LogEvent {
 public:
  template <std::size_t N>
  consteval LogEvent(const char (&name)[N]) : name_(name, N - 1) {  // NOLINT: implicit on purpose
    if (name_.empty()) NotALogEventName();
    for (char c : name_) {
      if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) NotALogEventName();
    }
  }
  constexpr std::string_view view() const { return name_; }

 private:
  std::string_view name_;
};

struct LogField {
  LogKey key;
  std::string value;
};

// Writes one line: the time, `event`, then `fields` in order. Thread-safe.
void Log(LogEvent event, std::initializer_list<LogField> fields = {});

enum class LogFormat { kText, kJson };

// Parses a --log-format value ("text", "json"). Errors: INVALID_ARGUMENT
// naming the value.
absl::StatusOr<LogFormat> ParseLogFormat(std::string_view name);

// Sets the format of every later line (process-wide; default kText).
void SetLogFormat(LogFormat format);

// From now on, `secret` (8 bytes or more; shorter ones are ignored, they
// would blank ordinary words) is written as "[redacted]" wherever it
// appears in a value. Thread-safe.
void RegisterLogSecret(std::string_view secret);

// The line Log writes for `event` and `fields` (without the newline), in
// `format`, with `time` as its time stamp. For tests.
std::string FormatLogLine(LogFormat format, std::string_view time, LogEvent event,
                          std::initializer_list<LogField> fields);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_LOG_H_
