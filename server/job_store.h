// File: job_store.h
// -----------------------------------------------------------------------------
// Every job the server knows, with its state machine
//   QUEUED -> RUNNING -> SUCCEEDED | FAILED | CANCELLED,  QUEUED -> CANCELLED,
// its progress, and a change counter that watchers wait on. Thread-safe.
#ifndef MESHSEG_SERVER_JOB_STORE_H_
#define MESHSEG_SERVER_JOB_STORE_H_

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "meshseg/pipeline.h"
#include "meshseg/v1/service.pb.h"
#include "server/job_queue.h"

namespace meshseg::server {

// What a worker needs to run a job.
struct RunSpec {
  std::string input_path;
  PipelineParams params;
  std::stop_token stop;
};

// Returns true for SUCCEEDED, FAILED and CANCELLED.
bool IsTerminal(v1::JobState state);

class JobStore {
 public:
  // `queue` answers queue positions; it must outlive the store.
  explicit JobStore(const JobQueue& queue);

  // Returns a fresh id ("job-" and 16 hex digits) no job has.
  std::string NewId();

  // Adds a QUEUED job.
  void Add(const std::string& id, std::string file_name, int64_t upload_size,
           std::string input_path, PipelineParams params);

  // Forgets `id` (a job that could not be queued).
  void Remove(const std::string& id);

  // Returns the job with its queue position. Errors: NOT_FOUND.
  absl::StatusOr<v1::Job> Get(const std::string& id) const;

  // Returns all jobs, oldest first.
  std::vector<v1::Job> List() const;

  // Moves a QUEUED job to RUNNING; nullopt if it is not QUEUED (cancelled).
  std::optional<RunSpec> Start(const std::string& id);

  // Records the stage a RUNNING job is in and the fraction of it done.
  void Progress(const std::string& id, std::string_view stage, double fraction);

  // Moves a RUNNING job to its terminal state: SUCCEEDED if `status` is OK,
  // CANCELLED for a CANCELLED status, else FAILED with the status.
  void Finish(const std::string& id, const absl::Status& status, int64_t result_size,
              int64_t face_count, int region_count);

  enum class CancelOutcome { kWasQueued, kStopRequested };
  // Cancels a QUEUED job at once (the caller removes it from the queue and
  // the spool) or asks a RUNNING one to stop.
  // Errors: NOT_FOUND; FAILED_PRECONDITION for a finished job.
  absl::StatusOr<CancelOutcome> Cancel(const std::string& id, std::string_view reason);

  // Asks every RUNNING job to stop.
  void StopAll();

  // Waits until no job is RUNNING or `deadline`; true if none is.
  bool AwaitIdle(absl::Time deadline) const;

  // Forgets jobs that finished before `cutoff`; returns their ids.
  std::vector<std::string> Expire(absl::Time cutoff);

  // A counter that grows on every change of any job.
  int64_t generation() const;

  // Returns when generation() != `seen` or after `timeout`.
  void AwaitChange(int64_t seen, absl::Duration timeout) const;

 private:
  struct Record {
    v1::Job info;
    std::string input_path;
    PipelineParams params;
    std::stop_source stop;
  };

  v1::Job View(const Record& record) const ABSL_SHARED_LOCKS_REQUIRED(mu_);
  void Changed() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) { ++generation_; }

  const JobQueue& queue_;
  mutable absl::Mutex mu_;
  std::map<std::string, Record> jobs_ ABSL_GUARDED_BY(mu_);
  int64_t generation_ ABSL_GUARDED_BY(mu_) = 0;
  int running_ ABSL_GUARDED_BY(mu_) = 0;
  std::mt19937_64 rng_ ABSL_GUARDED_BY(mu_);
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_JOB_STORE_H_
