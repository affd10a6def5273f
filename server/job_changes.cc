#include "server/job_changes.h"

#include <utility>

namespace meshseg::server {

JobChanges::~JobChanges() = default;

JobChanges::Subscription::~Subscription() {
  absl::MutexLock lock(&owner_.mu_);
  if (queued_) --slot_->queued;
  if (--slot_->subscribers == 0) owner_.slots_.erase(job_id_);
}

int64_t JobChanges::Subscription::version() const {
  absl::MutexLock lock(&owner_.mu_);
  return slot_->version;
}

void JobChanges::Subscription::set_queued(bool queued) {
  absl::MutexLock lock(&owner_.mu_);
  if (queued == queued_) return;
  queued_ = queued;
  slot_->queued += queued ? 1 : -1;
}

bool JobChanges::Subscription::Await(int64_t seen, absl::Duration timeout) const {
  const absl::Time deadline = absl::Now() + timeout;
  absl::MutexLock lock(&owner_.mu_);
  while (slot_->version == seen) {
    // The slot's own condition variable: no other job's change wakes it.
    if (slot_->changed.WaitWithDeadline(&owner_.mu_, deadline)) break;
  }
  return slot_->version != seen;
}

std::unique_ptr<JobChanges::Subscription> JobChanges::Subscribe(const std::string& job_id) {
  absl::MutexLock lock(&mu_);
  std::unique_ptr<Subscription::Slot>& slot = slots_[job_id];
  if (slot == nullptr) slot = std::make_unique<Subscription::Slot>();
  ++slot->subscribers;
  return std::unique_ptr<Subscription>(new Subscription(*this, job_id, slot.get()));
}

void JobChanges::Bump(const std::string& job_id) {
  absl::MutexLock lock(&mu_);
  const auto it = slots_.find(job_id);
  if (it == slots_.end()) return;
  ++it->second->version;
  it->second->changed.SignalAll();
}

void JobChanges::BumpQueued() {
  absl::MutexLock lock(&mu_);
  for (auto& [id, slot] : slots_) {
    if (slot->queued == 0) continue;
    ++slot->version;
    slot->changed.SignalAll();
  }
}

void JobChanges::BumpAll() {
  absl::MutexLock lock(&mu_);
  for (auto& [id, slot] : slots_) {
    ++slot->version;
    slot->changed.SignalAll();
  }
}

int JobChanges::watched_jobs() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(slots_.size());
}

}  // namespace meshseg::server
