// File: redis_job_store.h
// -----------------------------------------------------------------------------
// The distributed JobStore: each job is a Redis hash "meshseg:job:<id>"
// (its JobRecord, serialized, plus state, attempts, progress, outcome and a
// cancel flag as fields), indexed by the sorted sets "meshseg:jobs" (by
// creation, for ListJobs) and "meshseg:finished" (by end, for expiry). Every
// transition is one Lua script, so two replicas never both move a job.
//
// Change notification: every change PUBLISHes the job id on the channel
// "meshseg:events". One subscriber thread per process turns these into the
// generation counter watchers wait on (no watcher polls Redis), and stops a
// job running here as soon as its cancel flag is set (checked on each
// event for that job and every 500 ms, so a cancel sent while the
// subscription was down still arrives).
#ifndef MESHSEG_SERVER_REDIS_JOB_STORE_H_
#define MESHSEG_SERVER_REDIS_JOB_STORE_H_

#include <map>
#include <thread>

#include "server/change_counter.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/redis_connection.h"

namespace meshseg::server {

class RedisJobStore final : public JobStore {
 public:
  // `queue` answers queue positions; both must outlive the store.
  RedisJobStore(RedisPool& pool, const JobQueue& queue);
  ~RedisJobStore() override;

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
  // Reads one job's hash; NOT_FOUND if it has none.
  absl::StatusOr<JobRecord> Read(const std::string& id) const;
  void Subscribe(std::stop_token stop);
  void CheckCancel(const std::string& id);

  RedisPool& pool_;
  const JobQueue& queue_;
  ChangeCounter changes_;
  std::jthread subscriber_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_REDIS_JOB_STORE_H_
