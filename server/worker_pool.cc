#include "server/worker_pool.h"

#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "meshseg/proto/convert.h"
#include "server/log.h"

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
absl::StatusOr<PipelineResult> RunGuarded(const JobRunner& runner, const RunSpec& spec,
                                          const RunContext& ctx) {
  try {
    return runner(spec.input_path, spec.params, ctx);
  } catch (const std::exception& e) {
    return absl::InternalError(absl::StrCat("pipeline threw: ", e.what()));
  } catch (...) {
    return absl::InternalError("pipeline threw a non-standard exception");
  }
}

}  // namespace

WorkerPool::WorkerPool(int workers, JobQueue& queue, JobStore& store, const Spool& spool,
                       JobRunner runner)
    : queue_(queue), store_(store), spool_(spool), runner_(std::move(runner)) {
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { Loop(); });
}

WorkerPool::~WorkerPool() { Join(); }

void WorkerPool::Join() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

void WorkerPool::Loop() {
  while (std::optional<std::string> id = queue_.Pop()) Run(*id);
}

void WorkerPool::Run(const std::string& job_id) {
  std::optional<RunSpec> spec = store_.Start(job_id);
  if (!spec) return;  // cancelled while it waited
  Log("job_started", {{"job", job_id}, {"input", std::filesystem::path(spec->input_path)
                                                      .filename()
                                                      .string()}});
  const absl::Time start = absl::Now();

  // Report a stage change or a step of at least 1 %, not every call.
  std::string last_stage;
  double last_fraction = -1.0;
  RunContext ctx;
  ctx.stop = spec->stop;
  ctx.on_progress = [&](std::string_view stage, double fraction) {
    if (stage == last_stage && std::abs(fraction - last_fraction) < 0.01 && fraction < 1.0) {
      return;
    }
    last_stage = std::string(stage);
    last_fraction = fraction;
    store_.Progress(job_id, stage, fraction);
  };

  absl::StatusOr<PipelineResult> result = RunGuarded(runner_, *spec, ctx);
  std::error_code ec;
  std::filesystem::remove(spec->input_path, ec);  // the upload is not needed any more

  absl::Status status = result.status();
  int64_t result_size = 0;
  int64_t faces = 0;
  int regions = 0;
  if (result.ok()) {
    absl::StatusOr<int64_t> size = WriteResult(*result, spool_.ResultPath(job_id));
    status = size.status();
    if (size.ok()) {
      result_size = *size;
      faces = static_cast<int64_t>(result->face_labels.size());
      regions = static_cast<int>(result->regions.size());
    }
  }
  if (!status.ok()) spool_.RemoveJob(job_id);  // no result: leave no file
  store_.Finish(job_id, status, result_size, faces, regions);
  Log("job_finished",
      {{"job", job_id},
       {"state", status.ok() ? "SUCCEEDED"
                 : status.code() == absl::StatusCode::kCancelled ? "CANCELLED"
                                                                 : "FAILED"},
       {"seconds", absl::StrFormat("%.3f", absl::ToDoubleSeconds(absl::Now() - start))},
       {"faces", absl::StrCat(faces)},
       {"regions", absl::StrCat(regions)},
       {"result_bytes", absl::StrCat(result_size)},
       {"error", std::string(status.message())}});
}

}  // namespace meshseg::server
