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
#include "meshseg/status_macros.h"
#include "server/log.h"
#include "server/retry.h"

namespace meshseg::server {
namespace {

// Writes the wire form of `result` to `path`; returns its size in bytes.
absl::StatusOr<int64_t> WriteResult(const PipelineResult& result, const std::string& path) {
  const v1::SegmentationResult message = ToProto(result);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out || !message.SerializeToOstream(&out) || !out.flush()) {
    return absl::InternalError(absl::StrCat("spool: cannot write result \"", path, "\""));
  }
  return static_cast<int64_t>(message.ByteSizeLong());
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
                       BlobStore& blobs, const Spool& scratch, JobRunner runner)
    : max_attempts_(max_attempts),
      queue_(queue),
      store_(store),
      blobs_(blobs),
      scratch_(scratch),
      runner_(std::move(runner)) {
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
  while (std::optional<Lease> lease = queue_.Pop()) Run(*lease);
}

absl::Status WorkerPool::Execute(const RunSpec& spec, JobOutput& output) {
  const std::string& job_id = spec.record.job().job_id();
  MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(spec.record.options()));
  MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(spec.record.format_hint()));
  MESHSEG_ASSIGN_OR_RETURN(const std::unique_ptr<LocalBlob> upload,
                           blobs_.Open(spec.record.upload_key()));

  // Report a stage change or a step of at least 1 %, not every call.
  std::string last_stage;
  double last_fraction = -1.0;
  RunContext ctx;
  ctx.stop = spec.stop;
  ctx.on_progress = [&](std::string_view stage, double fraction) {
    if (stage == last_stage && std::abs(fraction - last_fraction) < 0.01 && fraction < 1.0) {
      return;
    }
    last_stage = std::string(stage);
    last_fraction = fraction;
    store_.Progress(job_id, stage, fraction);
  };
  MESHSEG_ASSIGN_OR_RETURN(const PipelineResult result,
                           RunGuarded(runner_, upload->path(), params, ctx));
  const std::string scratch = scratch_.ScratchPath(job_id, "result.pb");
  MESHSEG_ASSIGN_OR_RETURN(output.result_size, WriteResult(result, scratch));
  if (absl::Status put = blobs_.Put(ResultKey(job_id), scratch); !put.ok()) {
    std::remove(scratch.c_str());
    return put;
  }
  output.face_count = static_cast<int64_t>(result.face_labels.size());
  output.region_count = static_cast<int>(result.regions.size());
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
  const absl::Time start = absl::Now();
  JobOutput output;
  const absl::Status status = Execute(started->spec, output);

  if (!status.ok() && store_.running().ReasonOf(job_id) == StopReason::kShutdown) {
    (void)blobs_.Remove(ResultKey(job_id));
    (void)RetryWhileUnavailable("release", job_id, give_up_.get_token(),
                                [&] { return store_.Release(job_id); });
    queue_.Release(lease);
    Log("job_released", {{"job", job_id}, {"reason", "server shutting down"}});
    return;
  }
  if (!status.ok()) (void)blobs_.Remove(ResultKey(job_id));  // no result: leave no file
  const absl::Status finished = RetryWhileUnavailable("finish", job_id, give_up_.get_token(), [&] {
    return store_.Finish(job_id, status, output);
  });
  if (!finished.ok()) return;                // not recorded: the queue hands it out again
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
}

}  // namespace meshseg::server
