// File: server_options.h
// -----------------------------------------------------------------------------
// What meshseg-server is configured with (its command-line flags), and the
// function a worker runs for each job (RunPipeline; tests may pass another).
#ifndef MESHSEG_SERVER_SERVER_OPTIONS_H_
#define MESHSEG_SERVER_SERVER_OPTIONS_H_

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/time/time.h"
#include "meshseg/pipeline.h"
#include "meshseg/run_context.h"
#include "server/credentials.h"

namespace meshseg::server {

// Runs one job: the input file, its params, the job's stop token and progress.
using JobRunner = std::function<absl::StatusOr<PipelineResult>(
    const std::string& input_path, const PipelineParams& params, const RunContext& ctx)>;

// What one process does: accept uploads and serve jobs (kApi), run jobs
// (kWorker), or both (kAll, the embedded default).
enum class Role { kAll, kApi, kWorker };

struct ServerOptions {
  // HOST:PORT to listen on; port 0 = an ephemeral port (see Server::port()).
  std::string listen = "127.0.0.1:50051";
  // kApi serves no jobs' work; kWorker listens only for health checks.
  Role role = Role::kAll;
  // Worker threads running jobs; 0 = one per CPU of the container's quota
  // (cgroup), else of the machine.
  int workers = 0;
  // Max jobs waiting in the queue (running jobs not counted).
  int queue_capacity = 64;
  // Max bytes of one upload.
  int64_t max_upload_bytes = int64_t{2} << 30;
  // Embedded mode: every job's upload, record and result, one folder per
  // job, recovered at start. Redis mode: local scratch for files in transit.
  // Locked: one server per spool.
  std::string spool_dir = "/tmp/meshseg-spool";
  // "" = embedded (in-process queue, the spool is the store); or
  // "redis://HOST:PORT[/DB]": a Redis Stream queue and Redis job records,
  // shared by every replica, with blobs in `blob_dir`.
  std::string queue = {};
  // Redis mode: uploads and results, a folder every replica reaches.
  std::string blob_dir = {};
  // A job whose worker died this many times ends FAILED.
  int max_attempts = 3;
  // Redis mode: a job whose worker has not heartbeaten for this long is
  // taken over by another worker (a new attempt).
  absl::Duration claim_after = absl::Seconds(30);
  // A finished job (and its result) is forgotten this long after it ended.
  absl::Duration result_ttl = absl::Hours(24);
  // Running jobs get this long to finish on shutdown before they are cancelled.
  absl::Duration shutdown_grace = absl::Seconds(30);
  // HOST:PORT of the Prometheus endpoint (GET /metrics); empty = none.
  std::string metrics_listen = {};
  // The job itself. Empty = RunPipeline.
  JobRunner runner = {};
  // TLS, mutual TLS, bearer tokens, --insecure (credentials.h).
  SecurityOptions security = {};
  // Admission. Bytes of memory the jobs running in this process may take
  // at once, by their estimated peak (pipeline.h's EstimateJobMemory); a
  // job that can never fit is refused at upload, one that fits later waits.
  // 0 = 85 % of the container's memory limit (cgroup), else of the
  // machine's memory; for --role api, 0 = not checked at upload (the
  // workers' own budget applies; give the workers' value to refuse early).
  int64_t memory_budget = 0;
  // Bytes each filesystem holding uploads keeps free; an upload whose
  // declared size would cut into it (with the uploads in flight) is refused
  // before its data is received.
  int64_t min_free_disk = int64_t{256} << 20;
  // Streaming calls (Upload, WatchJob, GetResult) open at once, server-wide;
  // each holds a thread of the synchronous server while it waits. Further
  // ones get RESOURCE_EXHAUSTED. The thread pool is capped a little above.
  int max_concurrent_streams = 256;
  // Serve gRPC server reflection (grpcurl and the like list and call the
  // API without .proto files). Off by default: it describes the whole API
  // to anyone who connects.
  bool reflection = false;
};

// Returns "all", "api" or "worker".
std::string RoleName(Role role);
// Parses a --role value. Errors: INVALID_ARGUMENT naming the value.
absl::StatusOr<Role> ParseRole(absl::string_view name);

// Returns the bytes `text` means: digits with an optional suffix k, M, G, T
// (powers of 1000) or Ki, Mi, Gi, Ti (powers of 1024), e.g. "6Gi".
// Errors: INVALID_ARGUMENT naming `flag` and the text.
absl::StatusOr<int64_t> ParseByteSize(absl::string_view text, absl::string_view flag);

// Returns the default memory budget: 85 % of the cgroup memory limit, else
// of the machine's physical memory (the rest is the server's own: gRPC
// buffers, upload chunks, the job records).
int64_t DefaultMemoryBudget();

// Returns the options with defaults filled in (workers, memory budget,
// runner).
// Errors (INVALID_ARGUMENT): a value out of range, naming the flag.
absl::StatusOr<ServerOptions> ResolveOptions(ServerOptions options);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SERVER_OPTIONS_H_
