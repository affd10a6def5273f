#include "server/server_options.h"

#include <thread>

#include "absl/strings/str_cat.h"

namespace meshseg::server {

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
  if (options.workers == 0) {
    options.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  }
  if (!options.runner) {
    options.runner = [](const std::string& path, const PipelineParams& params,
                        const RunContext& ctx) { return RunPipeline(path, params, ctx); };
  }
  return options;
}

}  // namespace meshseg::server
