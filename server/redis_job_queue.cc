#include "server/redis_job_queue.h"

#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <random>
#include <utility>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "server/log.h"
#include "server/metrics.h"

namespace meshseg::server {
namespace {

constexpr char kStream[] = "meshseg:queue";
constexpr char kGroup[] = "workers";
constexpr char kEntries[] = "meshseg:queue:entries";
constexpr char kBlockMs[] = "1000";

// A stream entry id "MS-SEQ" as a comparable pair.
std::pair<uint64_t, uint64_t> EntryOrder(const std::string& id) {
  std::pair<uint64_t, uint64_t> order{0, 0};
  const std::vector<std::string> parts = absl::StrSplit(id, '-');
  if (parts.size() == 2) {
    (void)absl::SimpleAtoi(parts[0], &order.first);
    (void)absl::SimpleAtoi(parts[1], &order.second);
  }
  return order;
}

// The lease in a stream entry [id, [field, value, ...]]; nullopt for an
// entry whose content was deleted.
std::optional<Lease> LeaseOf(const RedisValue& entry) {
  if (entry.elements.size() != 2 || entry.elements[1].elements.size() < 2) return std::nullopt;
  return Lease{.job_id = entry.elements[1].elements[1].str, .entry = entry.elements[0].str};
}

}  // namespace

std::string NewConsumerName() {
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  return absl::StrFormat("%s-%d-%08x", host, getpid(),
                         static_cast<uint32_t>(std::random_device{}()));
}

RedisJobQueue::RedisJobQueue(RedisPool& pool, int capacity, absl::Duration claim_after,
                             std::string consumer)
    : pool_(pool), capacity_(capacity), claim_after_(claim_after), consumer_(std::move(consumer)) {
  heartbeat_ = std::jthread([this](std::stop_token stop) { Heartbeat(stop); });
}

RedisJobQueue::~RedisJobQueue() {
  heartbeat_.request_stop();
  if (heartbeat_.joinable()) heartbeat_.join();
}

bool RedisJobQueue::closed() const {
  absl::MutexLock lock(&mu_);
  return closed_;
}

absl::Status RedisJobQueue::EnsureGroup() const {
  {
    absl::MutexLock lock(&mu_);
    if (group_ready_) return absl::OkStatus();
  }
  // "0": a group created after jobs were added still delivers them.
  absl::StatusOr<RedisValue> created =
      pool_.Command({"XGROUP", "CREATE", kStream, kGroup, "0", "MKSTREAM"});
  if (!created.ok() && !absl::StrContains(created.status().message(), "BUSYGROUP")) {
    return created.status();
  }
  absl::MutexLock lock(&mu_);
  group_ready_ = true;
  return absl::OkStatus();
}

absl::Status RedisJobQueue::Push(const std::string& job_id) {
  if (closed()) return absl::UnavailableError("job queue: server is shutting down");
  if (absl::Status s = EnsureGroup(); !s.ok()) return s;
  absl::StatusOr<RedisValue> entry = pool_.Command({"XADD", kStream, "*", "job", job_id});
  if (!entry.ok()) return entry.status();
  absl::StatusOr<RedisValue> mapped = pool_.Command({"HSET", kEntries, job_id, entry->str});
  return mapped.status();
}

absl::StatusOr<std::optional<Lease>> RedisJobQueue::TryPop() {
  if (absl::Status s = EnsureGroup(); !s.ok()) return s;
  absl::StatusOr<RedisValue> claimed =
      pool_.Command({"XAUTOCLAIM", kStream, kGroup, consumer_,
                     absl::StrCat(absl::ToInt64Milliseconds(claim_after_)), "0-0", "COUNT", "1"});
  if (!claimed.ok()) return claimed.status();
  if (claimed->elements.size() >= 2) {
    for (const RedisValue& entry : claimed->elements[1].elements) {
      if (std::optional<Lease> lease = LeaseOf(entry)) {
        Log("job_reclaimed", {{"job", lease->job_id},
                              {"entry", lease->entry},
                              {"idle_over", absl::FormatDuration(claim_after_)}});
        Metrics::Global().JobClaimed();
        return lease;
      }
    }
  }
  absl::StatusOr<RedisValue> read =
      pool_.Command({"XREADGROUP", "GROUP", kGroup, consumer_, "COUNT", "1", "BLOCK", kBlockMs,
                     "STREAMS", kStream, ">"});
  if (!read.ok()) return read.status();
  for (const RedisValue& stream : read->elements) {
    if (stream.elements.size() != 2) continue;
    for (const RedisValue& entry : stream.elements[1].elements) {
      if (std::optional<Lease> lease = LeaseOf(entry)) return lease;
    }
  }
  return std::nullopt;
}

std::optional<Lease> RedisJobQueue::Pop() {
  absl::Duration backoff = absl::Milliseconds(100);
  bool down = false;
  while (!closed()) {
    absl::StatusOr<std::optional<Lease>> lease = TryPop();
    if (!lease.ok()) {
      // A Redis that came back empty (no AOF) has no group: make it again.
      if (absl::StrContains(lease.status().message(), "NOGROUP")) {
        absl::MutexLock lock(&mu_);
        group_ready_ = false;
      }
      if (!down) Log("queue_unavailable", {{"error", std::string(lease.status().message())}});
      down = true;
      absl::SleepFor(backoff);
      backoff = std::min(backoff * 2, absl::Seconds(2));
      continue;
    }
    if (down) Log("queue_reachable_again");
    down = false;
    backoff = absl::Milliseconds(100);
    if (lease->has_value()) {
      absl::MutexLock lock(&mu_);
      held_.insert((*lease)->entry);
      return *std::move(*lease);
    }
  }
  return std::nullopt;
}

void RedisJobQueue::Done(const Lease& lease) {
  {
    absl::MutexLock lock(&mu_);
    held_.erase(lease.entry);
  }
  // Best effort: an entry left pending is claimed by another worker after
  // claim_after, which finds the job finished and acknowledges it.
  (void)pool_.Command({"XACK", kStream, kGroup, lease.entry});
  (void)pool_.Command({"XDEL", kStream, lease.entry});
  absl::StatusOr<RedisValue> mapped = pool_.Command({"HGET", kEntries, lease.job_id});
  if (mapped.ok() && mapped->str == lease.entry) {
    (void)pool_.Command({"HDEL", kEntries, lease.job_id});
  }
}

void RedisJobQueue::Release(const Lease& lease) {
  absl::StatusOr<RedisValue> entry = pool_.Command({"XADD", kStream, "*", "job", lease.job_id});
  if (entry.ok()) (void)pool_.Command({"HSET", kEntries, lease.job_id, entry->str});
  Done(lease);
}

bool RedisJobQueue::Remove(const std::string& job_id) {
  absl::StatusOr<RedisValue> entry = pool_.Command({"HGET", kEntries, job_id});
  if (!entry.ok() || entry->is_nil()) return false;
  absl::StatusOr<RedisValue> deleted = pool_.Command({"XDEL", kStream, entry->str});
  (void)pool_.Command({"HDEL", kEntries, job_id});
  return deleted.ok() && deleted->integer == 1;
}

int RedisJobQueue::Position(const std::string& job_id) const {
  absl::StatusOr<RedisValue> entry = pool_.Command({"HGET", kEntries, job_id});
  if (!entry.ok() || entry->is_nil()) return -1;
  absl::StatusOr<RedisValue> groups = pool_.Command({"XINFO", "GROUPS", kStream});
  if (!groups.ok()) return -1;
  std::string last = "0-0";
  for (const RedisValue& group : groups->elements) {
    for (size_t i = 0; i + 1 < group.elements.size(); i += 2) {
      if (group.elements[i].str == "last-delivered-id") last = group.elements[i + 1].str;
    }
  }
  if (EntryOrder(entry->str) <= EntryOrder(last)) return 0;  // handed to a worker
  absl::StatusOr<RedisValue> ahead =
      pool_.Command({"XRANGE", kStream, absl::StrCat("(", last), absl::StrCat("(", entry->str),
                     "COUNT", absl::StrCat(4 * capacity_ + 64)});
  return ahead.ok() ? static_cast<int>(ahead->elements.size()) : -1;
}

absl::StatusOr<int> RedisJobQueue::Size() const {
  if (absl::Status s = EnsureGroup(); !s.ok()) return s;
  absl::StatusOr<RedisValue> length = pool_.Command({"XLEN", kStream});
  if (!length.ok()) return length.status();
  absl::StatusOr<RedisValue> pending = pool_.Command({"XPENDING", kStream, kGroup});
  if (!pending.ok()) return pending.status();
  const int64_t held = pending->elements.empty() ? 0 : pending->elements[0].integer;
  return static_cast<int>(std::max<int64_t>(0, length->integer - held));
}

void RedisJobQueue::Close() {
  absl::MutexLock lock(&mu_);
  closed_ = true;
}

void RedisJobQueue::Heartbeat(std::stop_token stop) {
  const absl::Duration period =
      std::clamp(claim_after_ / 4, absl::Milliseconds(50), absl::Seconds(5));
  std::mutex mu;
  std::condition_variable_any cv;
  std::unique_lock<std::mutex> lock(mu);
  while (!cv.wait_for(lock, stop, absl::ToChronoMilliseconds(period), [] { return false; }) &&
         !stop.stop_requested()) {
    std::vector<std::string> args = {"XCLAIM", kStream, kGroup, consumer_, "0"};
    {
      absl::MutexLock held_lock(&mu_);
      if (held_.empty()) continue;
      args.insert(args.end(), held_.begin(), held_.end());
    }
    args.push_back("JUSTID");
    (void)pool_.Command(args);  // Redis down: the next beat tries again
  }
}

}  // namespace meshseg::server
