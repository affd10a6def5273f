// File: job_store.h
// -----------------------------------------------------------------------------
// Every job the service knows, with its state machine
//   QUEUED -> RUNNING -> SUCCEEDED | FAILED | CANCELLED,  QUEUED -> CANCELLED,
//   RUNNING -> QUEUED (released by a shutdown, or its worker died),
// its progress, attempts, and a change counter that watchers wait on.
// An interface: the embedded store (local_job_store.h, in memory and
// persisted to the spool) and the Redis store (redis_job_store.h, shared by
// every replica) are interchangeable. Thread-safe.
#ifndef MESHSEG_SERVER_JOB_STORE_H_
#define MESHSEG_SERVER_JOB_STORE_H_

#include <cstdint>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "meshseg/v1/service.pb.h"
#include "server/job_changes.h"
#include "server/job_record.pb.h"
#include "server/running_jobs.h"

namespace meshseg::server {

// Returns true for SUCCEEDED, FAILED and CANCELLED.
bool IsTerminal(v1::JobState state);

// Returns a fresh job id: "job-" and 16 random hex digits.
std::string NewJobId();

// What a worker needs to run a job it started.
struct RunSpec {
  JobRecord record;
  std::stop_token stop;
};

// What a finished job produced (SUCCEEDED only).
struct JobOutput {
  int64_t result_size = 0;
  std::string result_sha256 = "";  // lowercase hex
  int64_t face_count = 0;
  int region_count = 0;
  int64_t step_size = 0;  // bytes of the job's STEP file; 0 = none
};

class JobStore {
 public:
  virtual ~JobStore() = default;

  // Records a new QUEUED job (record.job holds id, file name, sizes, created
  // time, tenant, request id) and returns its id; or, when record.job has a
  // request_id and a job of the same tenant with that request_id is still
  // known, records nothing and returns that job's id (atomically: two
  // uploads with one request id never both create a job).
  // Errors: UNAVAILABLE (store unreachable), INTERNAL (not written).
  virtual absl::StatusOr<std::string> Create(JobRecord record) = 0;

  // Returns the id of the known job of `tenant` created with `request_id`,
  // or nullopt. Errors: UNAVAILABLE.
  virtual absl::StatusOr<std::optional<std::string>> FindRequest(
      const std::string& tenant, const std::string& request_id) const = 0;

  // Forgets `id` (a job that could not be queued).
  virtual void Remove(const std::string& id) = 0;

  // Returns the job with its queue position. Errors: NOT_FOUND, UNAVAILABLE.
  virtual absl::StatusOr<v1::Job> Get(const std::string& id) const = 0;

  // Returns all jobs, oldest first. Errors: UNAVAILABLE.
  virtual absl::StatusOr<std::vector<v1::Job>> List() const = 0;

  enum class StartOutcome { kRun, kNotRunnable, kGaveUp };
  struct Started {
    StartOutcome outcome = StartOutcome::kNotRunnable;
    RunSpec spec;  // kRun only
  };
  // Starts a new attempt of `id` on this process: a QUEUED job, or one left
  // RUNNING by a worker that died, becomes RUNNING with attempts + 1.
  // kNotRunnable: it is terminal (cancelled while it waited) or unknown.
  // kGaveUp: it was already started `max_attempts` times, so it now ends
  // FAILED ("worker died N times") instead of running again.
  // Errors: UNAVAILABLE.
  virtual absl::StatusOr<Started> Start(const std::string& id, int max_attempts) = 0;

  // Records the stage a RUNNING job is in and the fraction of it done.
  virtual void Progress(const std::string& id, std::string_view stage, double fraction) = 0;

  // Moves a RUNNING job to its terminal state: SUCCEEDED if `status` is OK,
  // CANCELLED for a CANCELLED status, else FAILED with the status; and stops
  // tracking it as running here. Errors: UNAVAILABLE (the caller retries).
  virtual absl::Status Finish(const std::string& id, const absl::Status& status,
                              const JobOutput& output) = 0;

  // Moves a RUNNING job back to QUEUED without counting the attempt (it was
  // stopped by a shutdown, not by its input). Errors: UNAVAILABLE.
  virtual absl::Status Release(const std::string& id) = 0;

  enum class CancelOutcome { kWasQueued, kStopRequested };
  // Cancels a QUEUED job at once (the caller removes it from the queue and
  // its upload) or asks a RUNNING one to stop, wherever it runs.
  // Errors: NOT_FOUND; FAILED_PRECONDITION for a finished job; UNAVAILABLE.
  virtual absl::StatusOr<CancelOutcome> Cancel(const std::string& id, std::string_view reason) = 0;

  // Forgets jobs that finished before `cutoff`; returns their ids (the
  // caller removes their results).
  virtual std::vector<std::string> Expire(absl::Time cutoff) = 0;

  // A counter that grows on every change of any job.
  virtual int64_t generation() const = 0;

  // Returns when generation() != `seen` or after `timeout`.
  virtual void AwaitChange(int64_t seen, absl::Duration timeout) const = 0;

  // The jobs running in this process (to stop them on shutdown).
  RunningJobs& running() { return running_; }

  // Per-job change notification, for watchers of one job (WatchJob): the
  // store bumps a job on each of its changes, and the watchers of queued
  // jobs when the queue moves.
  JobChanges& job_changes() { return job_changes_; }

 protected:
  RunningJobs running_;
  JobChanges job_changes_;
};

// The terminal state a job ends in with `status`.
v1::JobState TerminalState(const absl::Status& status);

// The NOT_FOUND of a job id that is unknown, expired, or another tenant's
// (one message for all three: an id's existence is not revealed).
absl::Status JobNotFound(const std::string& id);

// The message of a job given up after `attempts` starts (of `max_attempts`).
std::string GaveUpMessage(int attempts, int max_attempts);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_JOB_STORE_H_
