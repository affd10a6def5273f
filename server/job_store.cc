#include "server/job_store.h"

#include <random>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/synchronization/mutex.h"

namespace meshseg::server {

bool IsTerminal(v1::JobState state) {
  return state == v1::JOB_STATE_SUCCEEDED || state == v1::JOB_STATE_FAILED ||
         state == v1::JOB_STATE_CANCELLED;
}

std::string NewJobId() {
  // 64 random bits: replicas draw ids independently, so a collision needs
  // ~4e9 jobs alive at once (birthday bound) to become likely.
  static absl::Mutex mu;
  static std::mt19937_64 rng{std::random_device{}()};  // guarded by mu
  absl::MutexLock lock(&mu);
  return absl::StrFormat("job-%016x", rng());
}

v1::JobState TerminalState(const absl::Status& status) {
  if (status.ok()) return v1::JOB_STATE_SUCCEEDED;
  if (status.code() == absl::StatusCode::kCancelled) return v1::JOB_STATE_CANCELLED;
  return v1::JOB_STATE_FAILED;
}

absl::Status JobNotFound(const std::string& id) {
  return absl::NotFoundError(
      absl::StrCat("job \"", id.substr(0, 64), "\" not found (unknown or expired)"));
}

std::string GaveUpMessage(int attempts, int max_attempts) {
  return absl::StrCat("worker died ", attempts, " times running this job (--max-attempts ",
                      max_attempts, "); not run again");
}

}  // namespace meshseg::server
