// File: worker_pool.h
// -----------------------------------------------------------------------------
// N threads that take job ids from the queue and run them: the runner
// (RunPipeline) on the spooled upload with the job's stop token and a progress
// callback, then the result written to the spool, the upload removed, the
// job finished in the store, one log line.
#ifndef MESHSEG_SERVER_WORKER_POOL_H_
#define MESHSEG_SERVER_WORKER_POOL_H_

#include <string>
#include <thread>
#include <vector>

#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/server_options.h"
#include "server/spool.h"

namespace meshseg::server {

class WorkerPool {
 public:
  // Starts `workers` threads. All references must outlive the pool.
  WorkerPool(int workers, JobQueue& queue, JobStore& store, const Spool& spool,
             JobRunner runner);
  // Joins the threads; the queue must have been closed.
  ~WorkerPool();

  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Waits for every thread to return (after JobQueue::Close()).
  void Join();

 private:
  void Loop();
  void Run(const std::string& job_id);

  JobQueue& queue_;
  JobStore& store_;
  const Spool& spool_;
  JobRunner runner_;
  std::vector<std::thread> threads_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_WORKER_POOL_H_
