#include "server/server_options.h"

#include <algorithm>

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
    return absl::InvalidArgumentError(absl::StrCat(
        "--result-ttl must be positive, got ", absl::FormatDuration(options.result_ttl)));
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
  if (options.workers == 0) options.workers = std::max(1, ProcessCpuLimit().workers);
  if (!options.runner) {
    options.runner = [](const std::string& path, const PipelineParams& params,
                        const RunContext& ctx) { return RunPipeline(path, params, ctx); };
  }
  return options;
}

}  // namespace meshseg::server
