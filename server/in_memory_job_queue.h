// File: in_memory_job_queue.h
// -----------------------------------------------------------------------------
// The embedded default JobQueue: a bounded FIFO guarded by a mutex. What it
// holds is rebuilt from the spool's job records after a restart.
#ifndef MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_
#define MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_

#include <deque>

#include "absl/synchronization/mutex.h"
#include "server/job_queue.h"

namespace meshseg::server {

class InMemoryJobQueue final : public JobQueue {
 public:
  explicit InMemoryJobQueue(int capacity) : capacity_(capacity) {}

  // Appends jobs recovered from the spool, in order, whatever the capacity
  // (they were accepted before the restart).
  void Restore(const std::vector<std::string>& job_ids);

  absl::Status Push(const std::string& job_id) override;
  std::optional<Lease> Pop() override;
  void Done(const Lease& /*lease*/) override {}
  // The job store keeps the job QUEUED; recovery queues it again.
  void Release(const Lease& /*lease*/) override {}
  bool Remove(const std::string& job_id) override;
  int Position(const std::string& job_id) const override;
  absl::StatusOr<int> Size() const override;
  int Capacity() const override { return capacity_; }
  void Close() override;

 private:
  const int capacity_;
  mutable absl::Mutex mu_;
  std::deque<std::string> ids_ ABSL_GUARDED_BY(mu_);
  bool closed_ ABSL_GUARDED_BY(mu_) = false;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_
