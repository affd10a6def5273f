// File: stream_limit.h
// -----------------------------------------------------------------------------
// A server-wide cap on open streaming calls (Upload, WatchJob, GetResult).
// The service runs on gRPC's synchronous API, where every open call holds
// one thread of the server's pool while it waits (for a chunk, for a job
// change); the pool is bounded (ResourceQuota::SetMaxThreads, server.cc)
// and this cap, set below that bound, refuses the call after the last slot
// with a message naming the flag, so stalled uploads and idle watchers can
// never take every thread. Thread-safe.
#ifndef MESHSEG_SERVER_STREAM_LIMIT_H_
#define MESHSEG_SERVER_STREAM_LIMIT_H_

#include <memory>
#include "absl/strings/string_view.h"

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"

namespace meshseg::server {

class StreamLimit {
 public:
  // A held slot, given back on destruction.
  class Slot {
   public:
    explicit Slot(StreamLimit& limit) : limit_(limit) {}
    ~Slot() {
      absl::MutexLock lock(&limit_.mu_);
      --limit_.open_;
    }
    Slot(const Slot&) = delete;
    Slot& operator=(const Slot&) = delete;

   private:
    StreamLimit& limit_;
  };

  explicit StreamLimit(int max_streams) : max_(max_streams) {}

  // Returns a slot for a `call` ("upload", "watch", "result") stream.
  // Errors: RESOURCE_EXHAUSTED when all slots are held.
  absl::StatusOr<std::unique_ptr<Slot>> Acquire(absl::string_view call) {
    absl::MutexLock lock(&mu_);
    if (open_ >= max_) {
      return absl::ResourceExhaustedError(
          absl::StrCat(call, ": server busy, ", open_, " streaming calls open (",
                       "--max-concurrent-streams ", max_, "); retry later"));
    }
    ++open_;
    return std::make_unique<Slot>(*this);
  }

  int open() const {
    absl::MutexLock lock(&mu_);
    return open_;
  }
  int max() const { return max_; }

 private:
  const int max_;
  mutable absl::Mutex mu_;
  int open_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_STREAM_LIMIT_H_
