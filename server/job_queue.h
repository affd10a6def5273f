// File: job_queue.h
// -----------------------------------------------------------------------------
// The queue of job ids waiting for a worker. An interface so the in-memory
// queue of the embedded default can be swapped for a shared one (DESIGN.md
// "--queue redis://") without touching the handlers or the workers.
#ifndef MESHSEG_SERVER_JOB_QUEUE_H_
#define MESHSEG_SERVER_JOB_QUEUE_H_

#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"

namespace meshseg::server {

class JobQueue {
 public:
  virtual ~JobQueue() = default;

  // Appends `job_id`. Errors: RESOURCE_EXHAUSTED when the queue holds its
  // capacity; UNAVAILABLE after Close().
  virtual absl::Status Push(const std::string& job_id) = 0;

  // Returns the oldest job id, blocking while the queue is empty; nullopt
  // once the queue is closed.
  virtual std::optional<std::string> Pop() = 0;

  // Removes a waiting job; false if it is not in the queue.
  virtual bool Remove(const std::string& job_id) = 0;

  // Returns the number of jobs ahead of `job_id`, or -1 if it is not queued.
  virtual int Position(const std::string& job_id) const = 0;

  // Returns the number of waiting jobs.
  virtual int Size() const = 0;

  // Returns the capacity Push() enforces.
  virtual int Capacity() const = 0;

  // Refuses further pushes, wakes every Pop() and returns the ids that were
  // still waiting (they will never be popped).
  virtual std::vector<std::string> Close() = 0;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_JOB_QUEUE_H_
