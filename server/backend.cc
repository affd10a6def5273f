#include "server/backend.h"

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "server/cgroup_limits.h"
#include "server/dir_blob_store.h"
#include "server/in_memory_job_queue.h"
#include "server/local_job_store.h"
#include "server/log.h"
#include "server/redis_job_queue.h"
#include "server/redis_job_store.h"

namespace meshseg::server {
namespace {

// Bounds connecting to Redis and each reply (XREADGROUP blocks 1 s).
constexpr absl::Duration kRedisTimeout = absl::Seconds(5);

void LogLimits(const ServerOptions& options) {
  const CpuLimit cpu = ProcessCpuLimit();
  const std::optional<int64_t> memory = ReadMemoryLimitBytes();
  Log("resource_limits",
      {{"cpu_source", cpu.source},
       {"cpu_quota_cores", cpu.quota_cores ? absl::StrCat(*cpu.quota_cores) : "none"},
       {"affinity_cores", absl::StrCat(cpu.affinity_cores)},
       {"workers", absl::StrCat(options.workers)},
       {"memory_limit_bytes", memory ? absl::StrCat(*memory) : "none"}});
}

absl::Status OpenEmbedded(const ServerOptions& options, Backend& b) {
  auto queue = std::make_unique<InMemoryJobQueue>(options.queue_capacity);
  auto store = std::make_unique<LocalJobStore>(*queue, *b.spool);
  const LocalJobStore::Recovery found = store->Recover(absl::Now() - options.result_ttl);
  queue->Restore(found.requeue);
  Log("spool_recovered", {{"spool", options.spool_dir},
                          {"requeued", absl::StrCat(found.requeue.size())},
                          {"interrupted", absl::StrCat(found.interrupted)},
                          {"served", absl::StrCat(found.served)},
                          {"expired", absl::StrCat(found.expired)}});
  b.queue = std::move(queue);
  b.store = std::move(store);
  b.blobs = &b.spool->blobs();
  return absl::OkStatus();
}

absl::Status OpenRedis(const ServerOptions& options, Backend& b) {
  MESHSEG_ASSIGN_OR_RETURN(const RedisAddress address, ParseRedisUrl(options.queue));
  MESHSEG_ASSIGN_OR_RETURN(b.shared_blobs, DirBlobStore::Create(options.blob_dir));
  b.redis = std::make_unique<RedisPool>(address, kRedisTimeout);
  if (absl::StatusOr<RedisValue> pong = b.redis->Command({"PING"}); !pong.ok()) {
    Log("redis_unavailable_at_start",
        {{"redis", address.text}, {"error", std::string(pong.status().message())}});
  }
  b.queue = std::make_unique<RedisJobQueue>(*b.redis, options.queue_capacity, options.claim_after,
                                            NewConsumerName());
  b.store = std::make_unique<RedisJobStore>(*b.redis, *b.queue);
  b.blobs = b.shared_blobs.get();
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<std::unique_ptr<Backend>> OpenBackend(const ServerOptions& options) {
  auto b = std::make_unique<Backend>();
  MESHSEG_ASSIGN_OR_RETURN(b->spool, Spool::Open(options.spool_dir));
  LogLimits(options);
  if (options.queue.empty()) {
    MESHSEG_RETURN_IF_ERROR(OpenEmbedded(options, *b));
  } else {
    MESHSEG_RETURN_IF_ERROR(OpenRedis(options, *b));
  }
  return b;
}

}  // namespace meshseg::server
