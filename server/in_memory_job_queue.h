// File: in_memory_job_queue.h
// -----------------------------------------------------------------------------
// The embedded default JobQueue: a bounded FIFO guarded by a mutex.
#ifndef MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_
#define MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_

#include <deque>

#include "absl/synchronization/mutex.h"
#include "server/job_queue.h"

namespace meshseg::server {

class InMemoryJobQueue final : public JobQueue {
 public:
  explicit InMemoryJobQueue(int capacity) : capacity_(capacity) {}

  absl::Status Push(const std::string& job_id) override;
  std::optional<std::string> Pop() override;
  bool Remove(const std::string& job_id) override;
  int Position(const std::string& job_id) const override;
  int Size() const override;
  int Capacity() const override { return capacity_; }
  std::vector<std::string> Close() override;

 private:
  const int capacity_;
  mutable absl::Mutex mu_;
  std::deque<std::string> ids_ ABSL_GUARDED_BY(mu_);
  bool closed_ ABSL_GUARDED_BY(mu_) = false;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_IN_MEMORY_JOB_QUEUE_H_
