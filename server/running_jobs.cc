#include "server/running_jobs.h"

namespace meshseg::server {

std::stop_token RunningJobs::Add(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Entry& entry = jobs_[id];
  entry = Entry{};
  return entry.stop.get_token();
}

void RunningJobs::Erase(const std::string& id) {
  absl::MutexLock lock(&mu_);
  jobs_.erase(id);
}

bool RunningJobs::Stop(const std::string& id, StopReason reason) {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return false;
  if (it->second.reason == StopReason::kNone) it->second.reason = reason;
  it->second.stop.request_stop();
  return true;
}

void RunningJobs::StopAll(StopReason reason) {
  absl::MutexLock lock(&mu_);
  for (auto& [id, entry] : jobs_) {
    if (entry.reason == StopReason::kNone) entry.reason = reason;
    entry.stop.request_stop();
  }
}

StopReason RunningJobs::ReasonOf(const std::string& id) const {
  absl::MutexLock lock(&mu_);
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? StopReason::kNone : it->second.reason;
}

std::vector<std::string> RunningJobs::Ids() const {
  absl::MutexLock lock(&mu_);
  std::vector<std::string> ids;
  for (const auto& [id, entry] : jobs_) ids.push_back(id);
  return ids;
}

bool RunningJobs::AwaitIdle(absl::Time deadline) const {
  absl::MutexLock lock(&mu_);
  const auto idle = [this]() ABSL_NO_THREAD_SAFETY_ANALYSIS { return jobs_.empty(); };
  return mu_.AwaitWithDeadline(absl::Condition(&idle), deadline);
}

}  // namespace meshseg::server
