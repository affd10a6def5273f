#include "server/log.h"

#include <cstdio>
#include <mutex>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
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

}  // namespace

void Log(std::string_view event, std::initializer_list<LogField> fields) {
  std::string line = absl::StrCat(
      "ts=", absl::FormatTime("%Y-%m-%dT%H:%M:%E3SZ", absl::Now(), absl::UTCTimeZone()),
      " event=", Quoted(event));
  for (const auto& [key, value] : fields) absl::StrAppend(&line, " ", std::string(key), "=", Quoted(value));
  line.push_back('\n');
  static std::mutex mu;  // keeps lines from interleaving
  std::lock_guard<std::mutex> lock(mu);
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
}

}  // namespace meshseg::server
