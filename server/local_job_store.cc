#include "server/local_job_store.h"

#include <algorithm>
#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/grpc_status.h"
#include "server/log.h"

namespace meshseg::server {
namespace {

int64_t NowUnixMs() { return absl::ToUnixMillis(absl::Now()); }

}  // namespace

void LocalJobStore::Persist(const JobRecord& record) const {
  if (absl::Status s = spool_.WriteRecord(record); !s.ok()) {
    Log("job_record_not_written", {{"job", record.job().job_id()}, {"error", s.ToString()}});
  }
}

LocalJobStore::Recovery LocalJobStore::Recover(absl::Time cutoff) {
  const int64_t cutoff_ms = absl::ToUnixMillis(cutoff);
  Spool::Recovered found = spool_.Recover();
  for (const Spool::Skipped& s : found.skipped) {
    Log("spool_folder_skipped", {{"folder", s.folder}, {"reason", s.reason}});
  }
  Recovery out;
  absl::MutexLock lock(&mu_);
  for (JobRecord& record : found.records) {
    v1::Job& job = *record.mutable_job();
    next_sequence_ = std::max(next_sequence_, record.sequence() + 1);
    if (IsTerminal(job.state())) {
      if (job.finished_unix_ms() < cutoff_ms) {
        spool_.RemoveJob(job.job_id());
        ++out.expired;
        continue;
      }
      ++out.served;
    } else {
      if (job.state() == v1::JOB_STATE_RUNNING) {
        ++out.interrupted;
        job.set_state(v1::JOB_STATE_QUEUED);
        job.clear_stage();
        job.clear_fraction();
        Persist(record);
      }
      out.requeue.push_back(job.job_id());
    }
    records_.Put(record);
  }
  job_changes_.BumpAll();
  changes_.Bump();
  return out;
}

absl::StatusOr<std::optional<std::string>> LocalJobStore::FindRequest(
    const std::string& tenant, const std::string& request_id) const {
  absl::ReaderMutexLock lock(&mu_);
  return records_.FindRequest(tenant, request_id);
}

absl::StatusOr<std::string> LocalJobStore::Create(JobRecord record) {
  absl::MutexLock lock(&mu_);
  if (std::optional<std::string> existing =
          records_.FindRequest(record.job().tenant(), record.job().request_id())) {
    return *existing;
  }
  record.set_format_version(kRecordFormat);
  record.set_sequence(next_sequence_++);
  record.mutable_job()->set_state(v1::JOB_STATE_QUEUED);
  if (absl::Status s = spool_.WriteRecord(record); !s.ok()) return s;
  const std::string id = record.job().job_id();
  records_.Put(record);
  Changed(id, /*queue_moved=*/false);
  return id;
}

void LocalJobStore::Remove(const std::string& id) {
  absl::MutexLock lock(&mu_);
  records_.Erase(id);
  spool_.RemoveJob(id);
  Changed(id, /*queue_moved=*/true);
}

v1::Job LocalJobStore::View(const JobRecord& record) const {
  v1::Job job = record.job();
  job.set_queue_position(job.state() == v1::JOB_STATE_QUEUED ? queue_.Position(job.job_id()) : -1);
  return job;
}

absl::StatusOr<v1::Job> LocalJobStore::Get(const std::string& id) const {
  absl::ReaderMutexLock lock(&mu_);
  const std::optional<JobRecord> record = records_.Get(id);
  if (!record) return JobNotFound(id);
  return View(*record);
}

absl::StatusOr<std::vector<v1::Job>> LocalJobStore::List() const {
  std::vector<std::pair<int64_t, v1::Job>> jobs;
  {
    absl::ReaderMutexLock lock(&mu_);
    records_.ForEach(
        [&](const JobRecord& record) { jobs.emplace_back(record.sequence(), View(record)); });
  }
  std::sort(jobs.begin(), jobs.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<v1::Job> out;
  for (auto& [sequence, job] : jobs) out.push_back(std::move(job));
  return out;
}

absl::StatusOr<JobStore::Started> LocalJobStore::Start(const std::string& id, int max_attempts) {
  absl::MutexLock lock(&mu_);
  std::optional<JobRecord> found = records_.Get(id);
  if (!found) return Started{};
  JobRecord& record = *found;
  v1::Job& job = *record.mutable_job();
  if (job.state() != v1::JOB_STATE_QUEUED && job.state() != v1::JOB_STATE_RUNNING) {
    return Started{};
  }
  Started out;
  if (job.attempts() >= max_attempts) {
    job.set_state(v1::JOB_STATE_FAILED);
    job.set_finished_unix_ms(NowUnixMs());
    SetJobError(absl::AbortedError(GaveUpMessage(job.attempts(), max_attempts)), &job);
    out.outcome = StartOutcome::kGaveUp;
    out.spec.record = record;
  } else {
    job.set_state(v1::JOB_STATE_RUNNING);
    job.set_attempts(job.attempts() + 1);
    job.set_started_unix_ms(NowUnixMs());
    out.outcome = StartOutcome::kRun;
    out.spec = RunSpec{record, running_.Add(id)};
  }
  records_.Put(record);
  // Durable before the job runs: a crash during the run counts this attempt.
  Persist(record);
  Changed(id, /*queue_moved=*/true);
  return out;
}

void LocalJobStore::Progress(const std::string& id, std::string_view stage, double fraction) {
  absl::MutexLock lock(&mu_);
  std::optional<JobRecord> record = RunningRecord(id);
  if (!record) return;
  v1::Job& job = *record->mutable_job();
  job.set_stage(std::string(stage));
  job.set_fraction(std::clamp(fraction, 0.0, 1.0));
  records_.Put(*record);
  Changed(id, /*queue_moved=*/false);
}

std::optional<JobRecord> LocalJobStore::RunningRecord(const std::string& id) const {
  std::optional<JobRecord> record = records_.Get(id);
  if (!record || record->job().state() != v1::JOB_STATE_RUNNING) return std::nullopt;
  return record;
}

absl::Status LocalJobStore::Finish(const std::string& id, const absl::Status& status,
                                   const JobOutput& output) {
  running_.Erase(id);
  absl::MutexLock lock(&mu_);
  std::optional<JobRecord> record = RunningRecord(id);
  if (!record) return absl::OkStatus();
  v1::Job& job = *record->mutable_job();
  job.set_state(TerminalState(status));
  job.set_finished_unix_ms(NowUnixMs());
  if (status.ok()) {
    job.set_fraction(1.0);
    job.set_result_size(output.result_size);
    job.set_result_sha256(output.result_sha256);
    job.set_face_count(output.face_count);
    job.set_region_count(output.region_count);
    job.set_step_size(output.step_size);
  } else {
    SetJobError(status, &job);
  }
  records_.Put(*record);
  Persist(*record);
  Changed(id, /*queue_moved=*/false);
  return absl::OkStatus();
}

absl::Status LocalJobStore::Release(const std::string& id) {
  running_.Erase(id);
  absl::MutexLock lock(&mu_);
  std::optional<JobRecord> record = RunningRecord(id);
  if (!record) return absl::OkStatus();
  v1::Job& job = *record->mutable_job();
  job.set_state(v1::JOB_STATE_QUEUED);
  job.set_attempts(std::max(0, job.attempts() - 1));
  job.clear_stage();
  job.clear_fraction();
  job.clear_started_unix_ms();
  records_.Put(*record);
  Persist(*record);
  Changed(id, /*queue_moved=*/true);
  return absl::OkStatus();
}

absl::StatusOr<JobStore::CancelOutcome> LocalJobStore::Cancel(const std::string& id,
                                                              std::string_view reason) {
  absl::MutexLock lock(&mu_);
  std::optional<JobRecord> record = records_.Get(id);
  if (!record) return JobNotFound(id);
  v1::Job& job = *record->mutable_job();
  if (IsTerminal(job.state())) {
    return absl::FailedPreconditionError(
        absl::StrCat("job \"", id, "\" already finished (", v1::JobState_Name(job.state()), ")"));
  }
  if (job.state() == v1::JOB_STATE_RUNNING) {
    running_.Stop(id, StopReason::kCancelled);
    return CancelOutcome::kStopRequested;
  }
  job.set_state(v1::JOB_STATE_CANCELLED);
  job.set_finished_unix_ms(NowUnixMs());
  SetJobError(absl::CancelledError(std::string(reason)), &job);
  records_.Put(*record);
  Persist(*record);
  Changed(id, /*queue_moved=*/true);
  return CancelOutcome::kWasQueued;
}

std::vector<std::string> LocalJobStore::Expire(absl::Time cutoff) {
  absl::MutexLock lock(&mu_);
  std::vector<std::string> expired = records_.FinishedBefore(absl::ToUnixMillis(cutoff));
  for (const std::string& id : expired) {
    spool_.RemoveJob(id);
    records_.Erase(id);
  }
  for (const std::string& id : expired) job_changes_.Bump(id);
  if (!expired.empty()) changes_.Bump();
  return expired;
}

int64_t LocalJobStore::generation() const { return changes_.value(); }

void LocalJobStore::AwaitChange(int64_t seen, absl::Duration timeout) const {
  changes_.Await(seen, timeout);
}

}  // namespace meshseg::server
