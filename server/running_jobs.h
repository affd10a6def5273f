// File: running_jobs.h
// -----------------------------------------------------------------------------
// The jobs this process is running now, each with the stop source its worker
// watches and why it was asked to stop. Both job stores use it: a cancel
// (local or arriving through Redis) or a shutdown stops a job through here.
// Thread-safe.
#ifndef MESHSEG_SERVER_RUNNING_JOBS_H_
#define MESHSEG_SERVER_RUNNING_JOBS_H_

#include <map>
#include <stop_token>
#include <string>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace meshseg::server {

enum class StopReason { kNone, kCancelled, kShutdown };

class RunningJobs {
 public:
  // Registers `id` as running here; returns the token its worker watches.
  std::stop_token Add(const std::string& id);
  // Unregisters `id` (its worker is done with it).
  void Erase(const std::string& id);
  // Asks `id` to stop, if it runs here; false if it does not.
  bool Stop(const std::string& id, StopReason reason);
  // Asks every job running here to stop.
  void StopAll(StopReason reason);
  // Why `id` was asked to stop (kNone if it was not, or is unknown).
  StopReason ReasonOf(const std::string& id) const;
  // Ids running here.
  std::vector<std::string> Ids() const;
  // Waits until none runs here or `deadline`; true if none does.
  bool AwaitIdle(absl::Time deadline) const;

 private:
  struct Entry {
    std::stop_source stop;
    StopReason reason = StopReason::kNone;
  };
  mutable absl::Mutex mu_;
  std::map<std::string, Entry> jobs_ ABSL_GUARDED_BY(mu_);
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_RUNNING_JOBS_H_
