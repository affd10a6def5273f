#include "server/memory_budget.h"

#include <algorithm>

namespace meshseg::server {

int64_t MemoryBudget::reserved() const {
  absl::MutexLock lock(&mu_);
  return reserved_;
}

int64_t MemoryBudget::peak_reserved() const {
  absl::MutexLock lock(&mu_);
  return peak_;
}

int MemoryBudget::waiting() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(waiting_.size());
}

bool MemoryBudget::Reserve(int64_t bytes, std::stop_token stop) {
  // absl::Mutex re-evaluates waiters' conditions when it is released:
  // taking it once on stop makes them see the request. (Registered before
  // locking: it runs at once, here, if stop was already requested.)
  std::stop_callback wake(stop, [this] { absl::MutexLock wake_lock(&mu_); });
  absl::MutexLock lock(&mu_);
  const int64_t ticket = next_ticket_++;
  waiting_.push_back(ticket);
  const auto ready = [&]() ABSL_NO_THREAD_SAFETY_ANALYSIS {
    return stop.stop_requested() || (waiting_.front() == ticket && reserved_ + bytes <= total_);
  };
  mu_.Await(absl::Condition(&ready));
  waiting_.erase(std::find(waiting_.begin(), waiting_.end(), ticket));
  if (stop.stop_requested()) return false;
  reserved_ += bytes;
  peak_ = std::max(peak_, reserved_);
  return true;
}

void MemoryBudget::Release(int64_t bytes) {
  absl::MutexLock lock(&mu_);
  reserved_ -= bytes;
}

bool MemoryBudget::AwaitNoWaiter(std::stop_token stop) {
  std::stop_callback wake(stop, [this] { absl::MutexLock wake_lock(&mu_); });
  absl::MutexLock lock(&mu_);
  const auto ready = [&]() ABSL_NO_THREAD_SAFETY_ANALYSIS {
    return stop.stop_requested() || waiting_.empty();
  };
  mu_.Await(absl::Condition(&ready));
  return !stop.stop_requested();
}

}  // namespace meshseg::server
