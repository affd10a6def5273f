// File: memory_budget.h
// -----------------------------------------------------------------------------
// The memory this process's workers may give jobs at once (--memory-budget)
// and the reservations held against it: a worker reserves a job's estimated
// peak (pipeline.h's EstimateJobMemory) before it starts the job and
// releases it when the job ends, so the jobs running here never add up to
// more than the budget. Requests are granted in the order they were made: a
// large job waiting for room is not overtaken (and starved) by smaller ones
// behind it. Thread-safe.
#ifndef MESHSEG_SERVER_MEMORY_BUDGET_H_
#define MESHSEG_SERVER_MEMORY_BUDGET_H_

#include <cstdint>
#include <deque>
#include <stop_token>

#include "absl/synchronization/mutex.h"

namespace meshseg::server {

class MemoryBudget {
 public:
  explicit MemoryBudget(int64_t total_bytes) : total_(total_bytes) {}

  int64_t total() const { return total_; }
  // Bytes reserved now, and the most ever reserved at once.
  int64_t reserved() const;
  int64_t peak_reserved() const;
  // Requests waiting now.
  int waiting() const;

  // Blocks until `bytes` fit next to the reservations held and every earlier
  // request was granted, then reserves them; returns false, reserving
  // nothing, once `stop` is requested. `bytes` must be <= total().
  bool Reserve(int64_t bytes, std::stop_token stop);

  // Gives back what Reserve() took.
  void Release(int64_t bytes);

  // Blocks while a Reserve() waits; returns false once `stop` is requested.
  // A worker calls it before taking a job from the queue, so a process
  // holds at most one job waiting for memory and leaves the rest queued
  // (for its other threads later, or for other worker processes).
  bool AwaitNoWaiter(std::stop_token stop);

 private:
  const int64_t total_;
  mutable absl::Mutex mu_;
  int64_t reserved_ ABSL_GUARDED_BY(mu_) = 0;
  int64_t peak_ ABSL_GUARDED_BY(mu_) = 0;
  int64_t next_ticket_ ABSL_GUARDED_BY(mu_) = 0;
  std::deque<int64_t> waiting_ ABSL_GUARDED_BY(mu_);  // tickets, oldest first
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_MEMORY_BUDGET_H_
