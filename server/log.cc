#include "server/log.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "server/log_json.h"
#include "meshseg/proto/utf8.h"

namespace meshseg::server {
namespace {

// Returns `value` as one token: quoted, with backslashes, quotes and
// newlines escaped, if it holds spaces, quotes, '=', controls or bytes that
// are not UTF-8 (a value may quote an uploaded file); the latter two then
// written as \xNN (utf8.h).
std::string Quoted(std::string_view value) {
  const std::string text = EscapeToUtf8(value);
  if (!value.empty() && text == value && value.find_first_of(" \"=") == std::string::npos) {
    return text;
  }
  const std::string escaped =
      absl::StrReplaceAll(std::string(value), {{"\\", "\\\\"}, {"\"", "\\\""}, {"\n", "\\n"}});
  return absl::StrCat("\"", EscapeToUtf8(escaped), "\"");
}

std::atomic<LogFormat> format{LogFormat::kText};

std::mutex& SecretsMutex() {
  static std::mutex mu;
  return mu;
}
std::vector<std::string>& Secrets() {
  static std::vector<std::string> secrets;
  return secrets;
}

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

// Blanks every registered secret, and the credential after "Bearer " (the
// scheme in any case) up to the next space, quote or comma, in `value`.
std::string Redacted(std::string_view value) {
  std::string in(value);
  {
    std::lock_guard<std::mutex> lock(SecretsMutex());
    for (const std::string& secret : Secrets()) in = absl::StrReplaceAll(in, {{secret, "[redacted]"}});
  }
  std::string out;
  std::size_t i = 0;
  while (i < in.size()) {
    if (i + 7 <= in.size() && absl::EqualsIgnoreCase(in.substr(i, 6), "bearer") &&
        IsBlank(in[i + 6])) {
      std::size_t start = i + 6;
      while (start < in.size() && IsBlank(in[start])) ++start;
      std::size_t end = start;
      while (end < in.size() && !absl::ascii_isspace(static_cast<unsigned char>(in[end])) &&
             in[end] != '"' && in[end] != ',') {
        ++end;
      }
      if (end > start) {
        absl::StrAppend(&out, in.substr(i, start - i), "[redacted]");
        i = end;
        continue;
      }
    }
    out.push_back(in[i++]);
  }
  return out;
}

std::string TextLine(std::string_view time, std::string_view event,
                     std::initializer_list<LogField> fields) {
  std::string line = absl::StrCat("ts=", std::string(time), " event=", Quoted(event));
  for (const auto& [key, value] : fields) {
    absl::StrAppend(&line, " ", std::string(key.view()), "=", Quoted(Redacted(value)));
  }
  return line;
}

std::string JsonLine(std::string_view time, std::string_view event,
                     std::initializer_list<LogField> fields) {
  std::string job_id, tenant, stage, duration = "null", rest;
  std::string_view level = LevelOf(event);
  for (const auto& [key, value] : fields) {
    const std::string clean = Redacted(value);
    double seconds = 0;
    // A job that failed is worth a look; one the user cancelled is not.
    if (key.view() == "state" && clean == "FAILED" && level == "info") level = "warn";
    if (key.view() == "job") {
      job_id = clean;
    } else if (key.view() == "tenant") {
      tenant = clean;
    } else if (key.view() == "stage") {
      stage = clean;
    } else if (key.view() == "seconds" && absl::SimpleAtod(clean, &seconds) &&
               std::isfinite(seconds)) {
      duration = absl::StrCat(seconds);
    } else {
      absl::StrAppend(&rest, ",", JsonString(key.view()), ":", JsonString(clean));
    }
  }
  return absl::StrCat("{\"time\":", JsonString(time), ",\"level\":", JsonString(level),
                      ",\"event\":", JsonString(event), ",\"job_id\":", JsonString(job_id),
                      ",\"tenant\":", JsonString(tenant), ",\"stage\":", JsonString(stage),
                      ",\"duration\":", duration, rest, "}");
}

}  // namespace

std::string FormatLogLine(LogFormat line_format, std::string_view time, LogEvent event,
                          std::initializer_list<LogField> fields) {
  return line_format == LogFormat::kJson ? JsonLine(time, event.view(), fields)
                                         : TextLine(time, event.view(), fields);
}

void Log(LogEvent event, std::initializer_list<LogField> fields) {
  const std::string time =
      absl::FormatTime("%Y-%m-%dT%H:%M:%E3SZ", absl::Now(), absl::UTCTimeZone());
  std::string line = FormatLogLine(format.load(), time, event, fields);
  line.push_back('\n');
  static std::mutex mu;  // keeps lines from interleaving
  std::lock_guard<std::mutex> lock(mu);
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
}

absl::StatusOr<LogFormat> ParseLogFormat(std::string_view name) {
  if (name == "text") return LogFormat::kText;
  if (name == "json") return LogFormat::kJson;
  return absl::InvalidArgumentError(absl::StrCat(
      "--log-format must be text or json, got \"", std::string(name.substr(0, 40)), "\""));
}

void SetLogFormat(LogFormat line_format) { format.store(line_format); }

void RegisterLogSecret(std::string_view secret) {
  if (secret.size() < 8) return;
  std::lock_guard<std::mutex> lock(SecretsMutex());
  Secrets().emplace_back(secret);
}

}  // namespace meshseg::server
