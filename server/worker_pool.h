// File: worker_pool.h
// -----------------------------------------------------------------------------
// N threads that take jobs from the queue and run them: start the attempt in
// the job store, the runner (RunPipeline) on the upload with the job's stop
// token and a progress callback, the result put in the blob store, the job
// finished in the store, the upload removed, the queue told, one log line
// per step. With a memory budget, a job's estimated peak memory is reserved
// before the runner starts and given back when it returns: a job that does
// not fit next to the running ones waits (stage "waiting for memory"), and
// while one waits no thread of this process takes another job from the
// queue. A job stopped by a shutdown is released (queued again), not
// cancelled. When the store cannot be reached the worker retries with
// backoff; it never drops an outcome and never spins.
//
// Test-only hook: if the environment variable MESHSEG_TEST_ABORT_ON_FILE
// names a job's file name, the worker process calls abort() when it starts
// that job (a "poison" input that kills its worker, for the recovery tests).
// Unset in production; never set it outside tests.
#ifndef MESHSEG_SERVER_WORKER_POOL_H_
#define MESHSEG_SERVER_WORKER_POOL_H_

#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "server/blob_store.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/memory_budget.h"
#include "server/server_options.h"
#include "server/spool.h"

namespace meshseg::server {

class WorkerPool {
 public:
  // Starts `workers` threads. All references must outlive the pool.
  // `budget` may be null (no memory admission).
  WorkerPool(int workers, int max_attempts, JobQueue& queue, JobStore& store, BlobStore& blobs,
             const Spool& scratch, JobRunner runner, MemoryBudget* budget = nullptr);
  // Joins the threads; the queue must have been closed.
  ~WorkerPool();

  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Waits for every thread to return (after JobQueue::Close()). Calls that
  // retry an unreachable store give up once `give_up` is requested.
  void Join();
  void GiveUpRetries() { give_up_.request_stop(); }

 private:
  void Loop();
  void Run(const Lease& lease);
  // Runs the started job; returns its outcome and fills `output`.
  absl::Status Execute(const RunSpec& spec, JobOutput& output);
  // Reserves the job's estimated peak in the budget, waiting for room;
  // returns the bytes reserved (0: no budget, or the estimate failed or is
  // over the whole budget, which RunPipeline then reports).
  // Errors: CANCELLED if the job is stopped while it waits.
  absl::StatusOr<int64_t> ReserveMemory(const std::string& job_id, const std::string& path,
                                        const PipelineParams& params, std::stop_token stop);

  const int max_attempts_;
  JobQueue& queue_;
  JobStore& store_;
  BlobStore& blobs_;
  const Spool& scratch_;
  JobRunner runner_;
  MemoryBudget* const budget_;
  std::string abort_on_file_;  // the test-only hook, empty = off
  std::stop_source give_up_;
  std::vector<std::thread> threads_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_WORKER_POOL_H_
