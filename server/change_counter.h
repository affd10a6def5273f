// File: change_counter.h
// -----------------------------------------------------------------------------
// A counter that grows on every change of any job, and a wait for it to
// move: what WatchJob sleeps on instead of polling the store. Thread-safe.
#ifndef MESHSEG_SERVER_CHANGE_COUNTER_H_
#define MESHSEG_SERVER_CHANGE_COUNTER_H_

#include <cstdint>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace meshseg::server {

class ChangeCounter {
 public:
  void Bump() {
    absl::MutexLock lock(&mu_);
    ++value_;
  }
  int64_t value() const {
    absl::MutexLock lock(&mu_);
    return value_;
  }
  // Returns when value() != `seen` or after `timeout`.
  void Await(int64_t seen, absl::Duration timeout) const {
    absl::MutexLock lock(&mu_);
    const auto changed = [this, seen]() ABSL_NO_THREAD_SAFETY_ANALYSIS { return value_ != seen; };
    mu_.AwaitWithTimeout(absl::Condition(&changed), timeout);
  }

 private:
  mutable absl::Mutex mu_;
  int64_t value_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_CHANGE_COUNTER_H_
