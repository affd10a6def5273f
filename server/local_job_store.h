// File: local_job_store.h
// -----------------------------------------------------------------------------
// The embedded mode's JobStore: every job in memory (its record on a
// RecordShelf, apart from the jobs' working memory, for the result TTL), and
// its record written to the spool on every state change (not on progress), so
// Recover() after a crash or a restart finds every accepted job again.
#ifndef MESHSEG_SERVER_LOCAL_JOB_STORE_H_
#define MESHSEG_SERVER_LOCAL_JOB_STORE_H_

#include "absl/synchronization/mutex.h"
#include "server/change_counter.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/record_shelf.h"
#include "server/spool.h"

namespace meshseg::server {

class LocalJobStore final : public JobStore {
 public:
  // `queue` answers queue positions; both must outlive the store.
  LocalJobStore(const JobQueue& queue, const Spool& spool) : queue_(queue), spool_(spool) {}

  // What recovery found.
  struct Recovery {
    std::vector<std::string> requeue;  // QUEUED and interrupted jobs, in order
    int served = 0;                    // finished jobs kept until their TTL
    int expired = 0;                   // finished jobs past their TTL, removed
    int interrupted = 0;               // were RUNNING when the server stopped
  };
  // Loads the spool's records: finished jobs are served until `cutoff`
  // passes their end (older ones are removed), interrupted ones go back to
  // QUEUED with their attempts kept. Logs each skipped folder.
  Recovery Recover(absl::Time cutoff);

  absl::StatusOr<std::string> Create(JobRecord record) override;
  absl::StatusOr<std::optional<std::string>> FindRequest(
      const std::string& tenant, const std::string& request_id) const override;
  void Remove(const std::string& id) override;
  absl::StatusOr<v1::Job> Get(const std::string& id) const override;
  absl::StatusOr<std::vector<v1::Job>> List() const override;
  absl::StatusOr<Started> Start(const std::string& id, int max_attempts) override;
  void Progress(const std::string& id, std::string_view stage, double fraction) override;
  absl::Status Finish(const std::string& id, const absl::Status& status,
                      const JobOutput& output) override;
  absl::Status Release(const std::string& id) override;
  absl::StatusOr<CancelOutcome> Cancel(const std::string& id, std::string_view reason) override;
  std::vector<std::string> Expire(absl::Time cutoff) override;
  int64_t generation() const override;
  void AwaitChange(int64_t seen, absl::Duration timeout) const override;

 private:
  v1::Job View(const JobRecord& record) const;
  // Writes `record` to the spool; a failure is logged (the job goes on in
  // memory, and the next state change writes it again).
  void Persist(const JobRecord& record) const;
  // The record of `id` if it is RUNNING, else nullopt.
  std::optional<JobRecord> RunningRecord(const std::string& id) const
      ABSL_SHARED_LOCKS_REQUIRED(mu_);
  // `id` changed; `queue_moved`: a job entered or left the queue's front
  // part, so queued jobs' positions changed.
  void Changed(const std::string& id, bool queue_moved) {
    changes_.Bump();
    job_changes_.Bump(id);
    if (queue_moved) job_changes_.BumpQueued();
  }
  const JobQueue& queue_;
  const Spool& spool_;
  mutable absl::Mutex mu_;
  RecordShelf records_ ABSL_GUARDED_BY(mu_);
  ChangeCounter changes_;
  int64_t next_sequence_ ABSL_GUARDED_BY(mu_) = 1;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_LOCAL_JOB_STORE_H_
