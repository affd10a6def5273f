// File: server_options.h
// -----------------------------------------------------------------------------
// What meshseg-server is configured with (its command-line flags), and the
// function a worker runs for each job (RunPipeline; tests may pass another).
#ifndef MESHSEG_SERVER_SERVER_OPTIONS_H_
#define MESHSEG_SERVER_SERVER_OPTIONS_H_

#include <cstdint>
#include <functional>
#include <string>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "meshseg/pipeline.h"
#include "meshseg/run_context.h"

namespace meshseg::server {

// Runs one job: the input file, its params, the job's stop token and progress.
using JobRunner = std::function<absl::StatusOr<PipelineResult>(
    const std::string& input_path, const PipelineParams& params, const RunContext& ctx)>;

struct ServerOptions {
  // HOST:PORT to listen on; port 0 = an ephemeral port (see Server::port()).
  std::string listen = "127.0.0.1:50051";
  // Worker threads running jobs; 0 = one per core.
  int workers = 0;
  // Max jobs waiting in the queue (running jobs not counted).
  int queue_capacity = 64;
  // Max bytes of one upload.
  int64_t max_upload_bytes = int64_t{2} << 30;
  // Uploads and results live here, one folder per job. Cleared at start.
  std::string spool_dir = "/tmp/meshseg-spool";
  // A finished job (and its result) is forgotten this long after it ended.
  absl::Duration result_ttl = absl::Hours(1);
  // Running jobs get this long to finish on shutdown before they are cancelled.
  absl::Duration shutdown_grace = absl::Seconds(30);
  // The job itself. Empty = RunPipeline.
  JobRunner runner = {};
};

// Returns the options with defaults filled in (workers, runner).
// Errors (INVALID_ARGUMENT): a value out of range, naming the flag.
absl::StatusOr<ServerOptions> ResolveOptions(ServerOptions options);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SERVER_OPTIONS_H_
