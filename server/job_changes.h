// File: job_changes.h
// -----------------------------------------------------------------------------
// Per-job change notification: what a WatchJob call sleeps on. A watcher
// subscribes to its own job and is woken only when that job changes (or,
// while the job waits in the queue, when the queue moves and so its
// position), never by other jobs' changes. Both job stores bump it: the
// embedded store on each state change, the Redis store from its pub/sub
// subscriber. Thread-safe.
#ifndef MESHSEG_SERVER_JOB_CHANGES_H_
#define MESHSEG_SERVER_JOB_CHANGES_H_

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace meshseg::server {

class JobChanges {
 public:
  // One watcher's registration; unregisters on destruction. Must not
  // outlive its JobChanges.
  class Subscription {
   public:
    ~Subscription();
    Subscription(const Subscription&) = delete;
    Subscription& operator=(const Subscription&) = delete;

    // Returns the job's change count now. Read it before reading the job,
    // then Await() it: a change in between is never missed.
    int64_t version() const;
    // Marks whether the job waits in the queue (then BumpQueued() wakes it).
    void set_queued(bool queued);
    // Returns true once version() != `seen`, false after `timeout`.
    bool Await(int64_t seen, absl::Duration timeout) const;

   private:
    friend class JobChanges;
    // One watched job: its change count and who waits on it (guarded by
    // the owner's mutex).
    struct Slot {
      int64_t version = 0;
      int subscribers = 0;
      int queued = 0;  // subscribers whose job waits in the queue
      absl::CondVar changed;
    };
    Subscription(JobChanges& owner, std::string job_id, Slot* slot)
        : owner_(owner), job_id_(std::move(job_id)), slot_(slot) {}
    JobChanges& owner_;
    const std::string job_id_;
    Slot* slot_;          // owned by owner_.slots_, alive while subscribed
    bool queued_ = false;  // guarded by owner_.mu_
  };

  JobChanges() = default;
  ~JobChanges();
  JobChanges(const JobChanges&) = delete;
  JobChanges& operator=(const JobChanges&) = delete;

  // Registers a watcher of `job_id`.
  std::unique_ptr<Subscription> Subscribe(const std::string& job_id);

  // `job_id` changed: wakes its watchers only (none: nothing to do).
  void Bump(const std::string& job_id);
  // The queue moved (a job left it): wakes the watchers of queued jobs.
  void BumpQueued();
  // Changes may have been missed (a lost notification channel): wakes all.
  void BumpAll();

  // Number of jobs with at least one watcher (for tests).
  int watched_jobs() const;

 private:
  mutable absl::Mutex mu_;
  std::map<std::string, std::unique_ptr<Subscription::Slot>> slots_ ABSL_GUARDED_BY(mu_);
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_JOB_CHANGES_H_
