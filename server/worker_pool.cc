#include "server/worker_pool.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/sha256.h"
#include "meshseg/status_macros.h"
#include "server/heap.h"
#include "server/log.h"
#include "server/metrics.h"
#include "server/retry.h"

namespace meshseg::server {
namespace {

// Writes the wire form of `result` to `path`; sets its size and SHA-256.
absl::Status WriteResult(const PipelineResult& result, const std::string& path, JobOutput& output) {
  const std::string bytes = ToProto(result).SerializeAsString();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out || !out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) ||
      !out.flush()) {
    return absl::InternalError(absl::StrCat("spool: cannot write result \"", path, "\""));
  }
  Sha256 digest;
  digest.Update(bytes);
  output.result_sha256 = digest.HexDigest();
  output.result_size = static_cast<int64_t>(bytes.size());
  return absl::OkStatus();
}

// Calls the runner; an exception escaping it becomes INTERNAL, so bad input
// can never take the server down.
absl::StatusOr<PipelineResult> RunGuarded(const JobRunner& runner, const std::string& path,
                                          const PipelineParams& params, const RunContext& ctx) {
  try {
    return runner(path, params, ctx);
  } catch (const std::exception& e) {
    return absl::InternalError(absl::StrCat("pipeline threw: ", e.what()));
  } catch (...) {
    return absl::InternalError("pipeline threw a non-standard exception");
  }
}

const char* StateName(const absl::Status& status) {
  return status.ok()                                     ? "SUCCEEDED"
         : status.code() == absl::StatusCode::kCancelled ? "CANCELLED"
                                                         : "FAILED";
}

}  // namespace

WorkerPool::WorkerPool(int workers, int max_attempts, JobQueue& queue, JobStore& store,
                       BlobStore& blobs, const Spool& scratch, JobRunner runner,
                       MemoryBudget* budget)
    : max_attempts_(max_attempts),
      queue_(queue),
      store_(store),
      blobs_(blobs),
      scratch_(scratch),
      runner_(std::move(runner)),
      budget_(budget) {
  if (const char* hook = std::getenv("MESHSEG_TEST_ABORT_ON_FILE")) abort_on_file_ = hook;
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { Loop(); });
}

WorkerPool::~WorkerPool() { Join(); }

void WorkerPool::Join() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

void WorkerPool::Loop() {
  while (true) {
    // A job waiting for memory here: leave the next ones in the queue (for
    // this process later, or for other workers).
    if (budget_ != nullptr && !budget_->AwaitNoWaiter(give_up_.get_token())) return;
    std::optional<Lease> lease = queue_.Pop();
    if (!lease.has_value()) return;
    Run(*lease);
  }
}

absl::StatusOr<int64_t> WorkerPool::ReserveMemory(const std::string& job_id,
                                                  const std::string& path,
                                                  const PipelineParams& params,
                                                  std::stop_token stop) {
  if (budget_ == nullptr) return 0;
  const absl::StatusOr<MemoryEstimate> estimate = EstimateJobMemory(path, params);
  if (!estimate.ok() || estimate->peak_bytes > budget_->total()) return 0;
  const int64_t bytes = estimate->peak_bytes;
  if (budget_->reserved() + bytes > budget_->total()) {
    store_.Progress(job_id, "waiting for memory", 0.0);
    Log("job_waiting_for_memory", {{"job", job_id},
                                   {"estimate", absl::StrCat(bytes)},
                                   {"reserved", absl::StrCat(budget_->reserved())},
                                   {"budget", absl::StrCat(budget_->total())}});
  }
  if (!budget_->Reserve(bytes, stop)) {
    return absl::CancelledError("stopped while waiting for memory");
  }
  return bytes;
}

absl::Status WorkerPool::Execute(const RunSpec& spec, JobOutput& output) {
  const std::string& job_id = spec.record.job().job_id();
  MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(spec.record.options()));
  MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(spec.record.format_hint()));
  MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(spec.record.raw_layout(), &params));
  params.volume.read.attached_data_only = true;  // read only the uploaded file
  params.include_mesh = spec.record.include_mesh();
  params.length_unit = spec.record.length_unit();
  if (spec.record.step()) {
    params.step_path = scratch_.ScratchPath(job_id, "result.step");
    MESHSEG_ASSIGN_OR_RETURN(params.brep.length_unit,
                             StepUnitFromWire(spec.record.step_unit(), spec.record.length_unit()));
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::unique_ptr<LocalBlob> upload,
                           blobs_.Open(spec.record.upload_key()));

  // Report a stage change or a step of at least 1 %, not every call.
  std::string last_stage;
  double last_fraction = -1.0;
  StageTimer stages(job_id);  // its destructor ends the last stage on an early return
  RunContext ctx;
  ctx.stop = spec.stop;
  ctx.on_progress = [&](std::string_view stage, double fraction) {
    stages.Enter(stage);
    if (stage == last_stage && std::abs(fraction - last_fraction) < 0.01 && fraction < 1.0) {
      return;
    }
    last_stage = std::string(stage);
    last_fraction = fraction;
    store_.Progress(job_id, stage, fraction);
  };
  if (budget_ != nullptr) params.memory_budget_bytes = budget_->total();
  MESHSEG_ASSIGN_OR_RETURN(const int64_t reserved,
                           ReserveMemory(job_id, upload->path(), params, spec.stop));
  absl::StatusOr<PipelineResult> run = RunGuarded(runner_, upload->path(), params, ctx);
  if (reserved > 0) budget_->Release(reserved);
  MESHSEG_ASSIGN_OR_RETURN(const PipelineResult result, std::move(run));
  stages.Finish();
  const std::string scratch = scratch_.ScratchPath(job_id, "result.pb");
  MESHSEG_RETURN_IF_ERROR(WriteResult(result, scratch, output));
  if (absl::Status put = blobs_.Put(ResultKey(job_id), scratch); !put.ok()) {
    std::remove(scratch.c_str());
    return put;
  }
  output.face_count = static_cast<int64_t>(result.face_labels.size());
  output.region_count = static_cast<int>(result.regions.size());
  // The STEP file, when asked for and written (else the result says why).
  if (!params.step_path.empty() && result.brep) {
    MESHSEG_RETURN_IF_ERROR(blobs_.Put(StepKey(job_id), params.step_path));
    output.step_size = result.brep->step_size;
  } else if (!params.step_path.empty()) {
    std::remove(params.step_path.c_str());
  }
  return absl::OkStatus();
}

void WorkerPool::Run(const Lease& lease) {
  const std::string& job_id = lease.job_id;
  const absl::StatusOr<JobStore::Started> started = RetryWhileUnavailable(
      "start", job_id, give_up_.get_token(), [&] { return store_.Start(job_id, max_attempts_); });
  if (!started.ok()) return;  // giving up on shutdown: the queue hands it out again
  if (started->outcome == JobStore::StartOutcome::kNotRunnable) {
    queue_.Done(lease);  // cancelled while it waited, or finished by an earlier attempt
    return;
  }
  const JobRecord& record = started->spec.record;
  if (started->outcome == JobStore::StartOutcome::kGaveUp) {
    (void)blobs_.Remove(record.upload_key());
    queue_.Done(lease);
    Metrics::Global().JobFinished("FAILED", std::nullopt);
    Log("job_finished", {{"job", job_id},
                         {"state", "FAILED"},
                         {"attempts", absl::StrCat(record.job().attempts())},
                         {"error", record.job().error_message()}});
    return;
  }
  Log("job_started", {{"job", job_id},
                      {"input", record.job().file_name()},
                      {"attempt", absl::StrCat(record.job().attempts())}});
  if (!abort_on_file_.empty() && record.job().file_name() == abort_on_file_) {
    Log("test_abort_on_file", {{"job", job_id}, {"file", abort_on_file_}});
    std::abort();  // test-only poison input (see worker_pool.h)
  }
  Metrics::Global().JobStarted(absl::FromUnixMillis(record.job().created_unix_ms()),
                              record.job().attempts());
  const absl::Time start = absl::Now();
  JobOutput output;
  const absl::Status status = Execute(started->spec, output);

  if (!status.ok() && store_.running().ReasonOf(job_id) == StopReason::kShutdown) {
    (void)blobs_.Remove(ResultKey(job_id));
    (void)blobs_.Remove(StepKey(job_id));
    (void)RetryWhileUnavailable("release", job_id, give_up_.get_token(),
                                [&] { return store_.Release(job_id); });
    queue_.Release(lease);
    Log("job_released", {{"job", job_id}, {"reason", "server shutting down"}});
    return;
  }
  if (!status.ok()) {  // no result: leave no file
    (void)blobs_.Remove(ResultKey(job_id));
    (void)blobs_.Remove(StepKey(job_id));
  }
  const absl::Status finished = RetryWhileUnavailable("finish", job_id, give_up_.get_token(), [&] {
    return store_.Finish(job_id, status, output);
  });
  if (!finished.ok()) return;                // not recorded: the queue hands it out again
  Metrics::Global().JobFinished(StateName(status), absl::Now() - start);
  if (status.ok()) Metrics::Global().ResultWritten(output.result_size);
  (void)blobs_.Remove(record.upload_key());  // the upload is not needed any more
  queue_.Done(lease);
  Log("job_finished",
      {{"job", job_id},
       {"state", StateName(status)},
       {"seconds", absl::StrFormat("%.3f", absl::ToDoubleSeconds(absl::Now() - start))},
       {"faces", absl::StrCat(output.face_count)},
       {"regions", absl::StrCat(output.region_count)},
       {"result_bytes", absl::StrCat(output.result_size)},
       {"error", std::string(status.message())}});
  // The job's mesh, graphs and result are freed by now, but malloc keeps
  // them in this thread's arena (and the pipeline's threads' arenas): give
  // the pages back, so the server's memory between jobs is what it holds,
  // not the sum of every arena's largest job (see server/heap.h).
  ReturnFreeHeap();
}

}  // namespace meshseg::server
