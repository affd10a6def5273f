#include "server/in_memory_job_queue.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace meshseg::server {

absl::Status InMemoryJobQueue::Push(const std::string& job_id) {
  absl::MutexLock lock(&mu_);
  if (closed_) return absl::UnavailableError("job queue: server is shutting down");
  if (static_cast<int>(ids_.size()) >= capacity_) {
    return absl::ResourceExhaustedError(
        absl::StrCat("job queue: full (", ids_.size(), " of ", capacity_, " jobs waiting)"));
  }
  ids_.push_back(job_id);
  return absl::OkStatus();
}

void InMemoryJobQueue::Restore(const std::vector<std::string>& job_ids) {
  absl::MutexLock lock(&mu_);
  ids_.insert(ids_.end(), job_ids.begin(), job_ids.end());
}

std::optional<Lease> InMemoryJobQueue::Pop() {
  absl::MutexLock lock(&mu_);
  mu_.Await(absl::Condition(
      +[](InMemoryJobQueue* q) ABSL_NO_THREAD_SAFETY_ANALYSIS {
        return q->closed_ || !q->ids_.empty();
      },
      this));
  if (closed_) return std::nullopt;
  Lease lease{.job_id = std::move(ids_.front()), .entry = {}};
  ids_.pop_front();
  return lease;
}

bool InMemoryJobQueue::Remove(const std::string& job_id) {
  absl::MutexLock lock(&mu_);
  const auto it = std::find(ids_.begin(), ids_.end(), job_id);
  if (it == ids_.end()) return false;
  ids_.erase(it);
  return true;
}

int InMemoryJobQueue::Position(const std::string& job_id) const {
  absl::MutexLock lock(&mu_);
  const auto it = std::find(ids_.begin(), ids_.end(), job_id);
  return it == ids_.end() ? -1 : static_cast<int>(it - ids_.begin());
}

absl::StatusOr<int> InMemoryJobQueue::Size() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(ids_.size());
}

void InMemoryJobQueue::Close() {
  absl::MutexLock lock(&mu_);
  closed_ = true;
}

}  // namespace meshseg::server
