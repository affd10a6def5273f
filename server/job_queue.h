// File: job_queue.h
// -----------------------------------------------------------------------------
// The queue of job ids waiting for a worker. An interface so the in-memory
// queue of the embedded default and the Redis Stream of the distributed mode
// (redis_job_queue.h) are interchangeable: the handlers and the workers do
// not know which one runs.
#ifndef MESHSEG_SERVER_JOB_QUEUE_H_
#define MESHSEG_SERVER_JOB_QUEUE_H_

#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace meshseg::server {

// A job handed to one worker. The worker calls Done() once the job's outcome
// is recorded; until then a shared queue may hand it to another worker if
// this one stops heartbeating.
struct Lease {
  std::string job_id;
  // The queue's own reference (a Redis Stream entry id; empty in memory).
  std::string entry;
};

class JobQueue {
 public:
  virtual ~JobQueue() = default;

  // Appends `job_id`. Errors: RESOURCE_EXHAUSTED when the queue holds its
  // capacity; UNAVAILABLE after Close() or when the queue cannot be reached.
  virtual absl::Status Push(const std::string& job_id) = 0;

  // Returns the next job, blocking while there is none; nullopt once the
  // queue is closed. Never spins: an unreachable queue is retried with
  // backoff.
  virtual std::optional<Lease> Pop() = 0;

  // The leased job's outcome is recorded: it leaves the queue for good.
  virtual void Done(const Lease& lease) = 0;

  // The leased job was stopped by a shutdown before it finished: it is
  // queued again (for this server after a restart, or another worker).
  virtual void Release(const Lease& lease) = 0;

  // Removes a waiting job; false if it is not in the queue.
  virtual bool Remove(const std::string& job_id) = 0;

  // Returns the number of jobs ahead of `job_id`, or -1 if it is not queued
  // (or the queue cannot be reached).
  virtual int Position(const std::string& job_id) const = 0;

  // Returns the number of waiting jobs. Errors: UNAVAILABLE.
  virtual absl::StatusOr<int> Size() const = 0;

  // Returns the capacity Push() enforces.
  virtual int Capacity() const = 0;

  // Refuses further pushes and wakes every Pop(). Jobs still waiting stay
  // queued (recorded by the job store or kept by the shared queue).
  virtual void Close() = 0;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_JOB_QUEUE_H_
