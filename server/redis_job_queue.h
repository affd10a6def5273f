// File: redis_job_queue.h
// -----------------------------------------------------------------------------
// The distributed JobQueue: a Redis Stream ("meshseg:queue") read by the
// consumer group "workers". Push is XADD; Pop is XREADGROUP (blocking 1 s
// at a time, so Close() is seen) after XAUTOCLAIM has looked for entries
// whose worker stopped heartbeating for `claim_after`; Done is XACK + XDEL.
// While a worker holds a job, a heartbeat thread re-claims its entries
// (XCLAIM ... JUSTID, which resets their idle time without counting a
// delivery) every claim_after / 4. A job id -> entry id hash answers
// Remove() and Position().
#ifndef MESHSEG_SERVER_REDIS_JOB_QUEUE_H_
#define MESHSEG_SERVER_REDIS_JOB_QUEUE_H_

#include <set>
#include <string>
#include <thread>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "server/job_queue.h"
#include "server/redis_connection.h"

namespace meshseg::server {

class RedisJobQueue final : public JobQueue {
 public:
  // `consumer` names this process in the group (host, pid, random).
  RedisJobQueue(RedisPool& pool, int capacity, absl::Duration claim_after, std::string consumer);
  ~RedisJobQueue() override;

  absl::Status Push(const std::string& job_id) override;
  std::optional<Lease> Pop() override;
  void Done(const Lease& lease) override;
  void Release(const Lease& lease) override;
  bool Remove(const std::string& job_id) override;
  int Position(const std::string& job_id) const override;
  absl::StatusOr<int> Size() const override;
  int Capacity() const override { return capacity_; }
  void Close() override;

 private:
  absl::Status EnsureGroup() const;
  // One try at taking a job: a stale one by XAUTOCLAIM, else a new one.
  absl::StatusOr<std::optional<Lease>> TryPop();
  void Heartbeat(std::stop_token stop);
  bool closed() const;

  RedisPool& pool_;
  const int capacity_;
  const absl::Duration claim_after_;
  const std::string consumer_;
  mutable absl::Mutex mu_;
  bool closed_ ABSL_GUARDED_BY(mu_) = false;
  std::set<std::string> held_ ABSL_GUARDED_BY(mu_);  // entry ids this process runs
  mutable bool group_ready_ ABSL_GUARDED_BY(mu_) = false;
  std::jthread heartbeat_;
};

// Returns a consumer name unique to this process: "HOST-PID-RANDOM".
std::string NewConsumerName();

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_REDIS_JOB_QUEUE_H_
