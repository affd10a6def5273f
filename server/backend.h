// File: backend.h
// -----------------------------------------------------------------------------
// The parts that differ between the embedded mode and the Redis mode,
// chosen once from the options: the job queue, the job store, the blob
// store and the local spool. Everything else (handlers, workers, sweeper)
// sees only the interfaces. Embedded: the spool is recovered here.
#ifndef MESHSEG_SERVER_BACKEND_H_
#define MESHSEG_SERVER_BACKEND_H_

#include <memory>

#include "absl/status/statusor.h"
#include "server/blob_store.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/redis_connection.h"
#include "server/server_options.h"
#include "server/spool.h"

namespace meshseg::server {

struct Backend {
  // Declared in the order they are built; destroyed in reverse (the store's
  // threads use the queue and the pool).
  std::unique_ptr<Spool> spool;
  std::unique_ptr<RedisPool> redis;         // Redis mode only
  std::unique_ptr<BlobStore> shared_blobs;  // Redis mode only (--blob-dir)
  std::unique_ptr<JobQueue> queue;
  std::unique_ptr<JobStore> store;
  BlobStore* blobs = nullptr;  // the spool's folders, or shared_blobs
};

// Opens the backend `options` select. Embedded: locks and recovers the spool
// (finished jobs served until their TTL, queued and interrupted ones queued
// again in their old order). Redis: an unreachable Redis is logged, not an
// error (the server retries and answers UNAVAILABLE meanwhile).
// Errors: the spool's or the blob store's.
absl::StatusOr<std::unique_ptr<Backend>> OpenBackend(const ServerOptions& options);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_BACKEND_H_
