#include "server/server_options.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <climits>
#include <utility>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "server/cgroup_limits.h"
#include "server/redis_connection.h"

namespace meshseg::server {

std::string RoleName(Role role) {
  switch (role) {
    case Role::kApi:
      return "api";
    case Role::kWorker:
      return "worker";
    default:
      return "all";
  }
}

absl::StatusOr<Role> ParseRole(absl::string_view name) {
  if (name == "all") return Role::kAll;
  if (name == "api") return Role::kApi;
  if (name == "worker") return Role::kWorker;
  return absl::InvalidArgumentError(
      absl::StrCat("--role must be all, api or worker, got \"", name, "\""));
}

absl::StatusOr<int64_t> ParseByteSize(absl::string_view text, absl::string_view flag) {
  static constexpr std::array<std::pair<absl::string_view, int64_t>, 8> kSuffixes = {{
      {"Ki", int64_t{1} << 10},
      {"Mi", int64_t{1} << 20},
      {"Gi", int64_t{1} << 30},
      {"Ti", int64_t{1} << 40},
      {"k", 1'000},
      {"M", 1'000'000},
      {"G", 1'000'000'000},
      {"T", 1'000'000'000'000},
  }};
  const absl::string_view trimmed = absl::StripAsciiWhitespace(text);
  absl::string_view digits = trimmed;
  int64_t unit = 1;
  for (const auto& [suffix, scale] : kSuffixes) {
    if (absl::EndsWith(trimmed, suffix)) {
      digits = trimmed.substr(0, trimmed.size() - suffix.size());
      unit = scale;
      break;
    }
  }
  int64_t value = 0;
  if (!absl::SimpleAtoi(digits, &value) || value < 0 || value > INT64_MAX / unit) {
    return absl::InvalidArgumentError(absl::StrCat(
        flag,
        " must be bytes with an optional suffix k, M, G, T, Ki, Mi, Gi, Ti (e.g. 6Gi), got \"",
        text, "\""));
  }
  return value * unit;
}

int64_t DefaultMemoryBudget() {
  std::optional<int64_t> limit = ReadMemoryLimitBytes();
  if (!limit.has_value()) {
    limit = static_cast<int64_t>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGESIZE);
  }
  return *limit / 100 * 85;
}

absl::StatusOr<ServerOptions> ResolveOptions(ServerOptions options) {
  if (options.listen.empty() || options.listen.find(':') == std::string::npos) {
    return absl::InvalidArgumentError(
        absl::StrCat("--listen must be HOST:PORT, got \"", options.listen, "\""));
  }
  if (options.workers < 0 || options.workers > 1024) {
    return absl::InvalidArgumentError(
        absl::StrCat("--workers must be in [0, 1024], got ", options.workers));
  }
  if (options.queue_capacity < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("--queue-capacity must be at least 1, got ", options.queue_capacity));
  }
  if (options.max_upload_bytes < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("--max-upload-bytes must be at least 1, got ", options.max_upload_bytes));
  }
  if (options.spool_dir.empty()) {
    return absl::InvalidArgumentError("--spool-dir must not be empty");
  }
  if (options.result_ttl <= absl::ZeroDuration()) {
    return absl::InvalidArgumentError(absl::StrCat("--result-ttl must be positive, got ",
                                                   absl::FormatDuration(options.result_ttl)));
  }
  if (options.max_attempts < 1 || options.max_attempts > 100) {
    return absl::InvalidArgumentError(
        absl::StrCat("--max-attempts must be in [1, 100], got ", options.max_attempts));
  }
  if (options.claim_after < absl::Milliseconds(200)) {
    return absl::InvalidArgumentError(absl::StrCat("--claim-after must be at least 200ms, got ",
                                                   absl::FormatDuration(options.claim_after)));
  }
  if (!options.queue.empty()) {
    MESHSEG_RETURN_IF_ERROR(ParseRedisUrl(options.queue).status());
    if (options.blob_dir.empty()) {
      return absl::InvalidArgumentError(
          "--blob-dir is required with --queue redis://... (a folder every replica reaches)");
    }
  } else if (options.role != Role::kAll) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--role ", RoleName(options.role),
        " needs a shared queue (--queue redis://HOST:PORT); the embedded mode is one process"));
  }
  if (options.memory_budget < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("--memory-budget must be >= 0, got ", options.memory_budget));
  }
  if (options.min_free_disk < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("--min-free-disk must be >= 0, got ", options.min_free_disk));
  }
  if (options.max_concurrent_streams < 1 || options.max_concurrent_streams > 100'000) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--max-concurrent-streams must be in [1, 100000], got ", options.max_concurrent_streams));
  }
  if (options.memory_budget == 0 && options.role != Role::kApi) {
    options.memory_budget = DefaultMemoryBudget();
  }
  if (options.workers == 0) options.workers = std::max(1, ProcessCpuLimit().workers);
  if (!options.runner) {
    options.runner = [](const std::string& path, const PipelineParams& params,
                        const RunContext& ctx) { return RunPipeline(path, params, ctx); };
  }
  return options;
}

}  // namespace meshseg::server
