#include "server/job_store.h"

#include <algorithm>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "meshseg/proto/grpc_status.h"

namespace meshseg::server {
namespace {

int64_t NowUnixMs() { return absl::ToUnixMillis(absl::Now()); }

v1::JobState TerminalState(const absl::Status& status) {
  if (status.ok()) return v1::JOB_STATE_SUCCEEDED;
  if (status.code() == absl::StatusCode::kCancelled) return v1::JOB_STATE_CANCELLED;
  return v1::JOB_STATE_FAILED;
}

}  // namespace

bool IsTerminal(v1::JobState state) {
  return state == v1::JOB_STATE_SUCCEEDED || state == v1::JOB_STATE_FAILED ||
         state == v1::JOB_STATE_CANCELLED;
}

JobStore::JobStore(const JobQueue& queue) : queue_(queue), rng_(std::random_device{}()) {}

std::string JobStore::NewId() {
  absl::MutexLock lock(&mu_);
  while (true) {
    std::string id = absl::StrFormat("job-%016x", rng_());
    if (!jobs_.contains(id)) return id;
  }
}

void JobStore::Add(const std::string& id, std::string file_name, int64_t upload_size,
                   std::string input_path, PipelineParams params) {
  absl::MutexLock lock(&mu_);
  Record& r = jobs_[id];
  r.info.set_job_id(id);
  r.info.set_state(v1::JOB_STATE_QUEUED);
  r.info.set_file_name(std::move(file_name));
  r.info.set_upload_size(upload_size);
  r.info.set_created_unix_ms(NowUnixMs());
  r.input_path = std::move(input_path);
  r.params = std::move(params);
  Changed();
}

void JobStore::Remove(const std::string& id) {
  absl::MutexLock lock(&mu_);
  jobs_.erase(id);
  Changed();
}

v1::Job JobStore::View(const Record& record) const {
  v1::Job job = record.info;
  job.set_queue_position(job.state() == v1::JOB_STATE_QUEUED ? queue_.Position(job.job_id())
                                                             : -1);
  return job;
}

absl::StatusOr<v1::Job> JobStore::Get(const std::string& id) const {
  absl::ReaderMutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) {
    return absl::NotFoundError(
        absl::StrCat("job \"", id.substr(0, 64), "\" not found (unknown or expired)"));
  }
  return View(it->second);
}

std::vector<v1::Job> JobStore::List() const {
  std::vector<v1::Job> jobs;
  {
    absl::ReaderMutexLock lock(&mu_);
    for (const auto& [id, record] : jobs_) jobs.push_back(View(record));
  }
  std::stable_sort(jobs.begin(), jobs.end(), [](const v1::Job& a, const v1::Job& b) {
    return a.created_unix_ms() < b.created_unix_ms();
  });
  return jobs;
}

std::optional<RunSpec> JobStore::Start(const std::string& id) {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.info.state() != v1::JOB_STATE_QUEUED) return std::nullopt;
  Record& r = it->second;
  r.info.set_state(v1::JOB_STATE_RUNNING);
  r.info.set_started_unix_ms(NowUnixMs());
  ++running_;
  Changed();
  return RunSpec{r.input_path, r.params, r.stop.get_token()};
}

void JobStore::Progress(const std::string& id, std::string_view stage, double fraction) {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.info.state() != v1::JOB_STATE_RUNNING) return;
  it->second.info.set_stage(std::string(stage));
  it->second.info.set_fraction(std::clamp(fraction, 0.0, 1.0));
  Changed();
}

void JobStore::Finish(const std::string& id, const absl::Status& status, int64_t result_size,
                      int64_t face_count, int region_count) {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.info.state() != v1::JOB_STATE_RUNNING) return;
  v1::Job& job = it->second.info;
  job.set_state(TerminalState(status));
  job.set_finished_unix_ms(NowUnixMs());
  if (status.ok()) {
    job.set_fraction(1.0);
    job.set_result_size(result_size);
    job.set_face_count(face_count);
    job.set_region_count(region_count);
  } else {
    SetJobError(status, &job);
  }
  --running_;
  Changed();
}

absl::StatusOr<JobStore::CancelOutcome> JobStore::Cancel(const std::string& id,
                                                         std::string_view reason) {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) {
    return absl::NotFoundError(
        absl::StrCat("job \"", id.substr(0, 64), "\" not found (unknown or expired)"));
  }
  v1::Job& job = it->second.info;
  if (IsTerminal(job.state())) {
    return absl::FailedPreconditionError(absl::StrCat(
        "job \"", id, "\" already finished (", v1::JobState_Name(job.state()), ")"));
  }
  if (job.state() == v1::JOB_STATE_RUNNING) {
    it->second.stop.request_stop();
    return CancelOutcome::kStopRequested;
  }
  job.set_state(v1::JOB_STATE_CANCELLED);
  job.set_finished_unix_ms(NowUnixMs());
  SetJobError(absl::CancelledError(std::string(reason)), &job);
  Changed();
  return CancelOutcome::kWasQueued;
}

void JobStore::StopAll() {
  absl::MutexLock lock(&mu_);
  for (auto& [id, record] : jobs_) {
    if (record.info.state() == v1::JOB_STATE_RUNNING) record.stop.request_stop();
  }
}

bool JobStore::AwaitIdle(absl::Time deadline) const {
  absl::MutexLock lock(&mu_);
  const auto idle = [this]() ABSL_NO_THREAD_SAFETY_ANALYSIS { return running_ == 0; };
  return mu_.AwaitWithDeadline(absl::Condition(&idle), deadline);
}

std::vector<std::string> JobStore::Expire(absl::Time cutoff) {
  const int64_t cutoff_ms = absl::ToUnixMillis(cutoff);
  std::vector<std::string> expired;
  absl::MutexLock lock(&mu_);
  for (auto it = jobs_.begin(); it != jobs_.end();) {
    const v1::Job& job = it->second.info;
    if (IsTerminal(job.state()) && job.finished_unix_ms() < cutoff_ms) {
      expired.push_back(it->first);
      it = jobs_.erase(it);
    } else {
      ++it;
    }
  }
  if (!expired.empty()) Changed();
  return expired;
}

int64_t JobStore::generation() const {
  absl::ReaderMutexLock lock(&mu_);
  return generation_;
}

void JobStore::AwaitChange(int64_t seen, absl::Duration timeout) const {
  absl::MutexLock lock(&mu_);
  const auto changed = [this, seen]() ABSL_NO_THREAD_SAFETY_ANALYSIS {
    return generation_ != seen;
  };
  mu_.AwaitWithTimeout(absl::Condition(&changed), timeout);
}

}  // namespace meshseg::server
