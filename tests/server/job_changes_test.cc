// JobChanges: a watcher is woken by its own job's changes, by the queue
// moving only while its job is queued, and by BumpAll; never by another
// job's change. Slots are freed with their last subscription.
#include "server/job_changes.h"

#include <gtest/gtest.h>

#include <thread>

#include "absl/time/clock.h"

namespace meshseg::server {
namespace {

constexpr absl::Duration kShort = absl::Milliseconds(50);

TEST(JobChanges, AWatcherWakesOnlyForItsOwnJob) {
  JobChanges changes;
  const auto a = changes.Subscribe("job-a");
  const int64_t seen = a->version();
  changes.Bump("job-b");
  changes.Bump("job-unwatched");
  EXPECT_FALSE(a->Await(seen, kShort));
  std::thread bump([&] {
    absl::SleepFor(absl::Milliseconds(20));
    changes.Bump("job-a");
  });
  const absl::Time start = absl::Now();
  EXPECT_TRUE(a->Await(seen, absl::Seconds(10)));
  EXPECT_LT(absl::Now() - start, absl::Seconds(5));  // woken, not timed out
  bump.join();
}

TEST(JobChanges, QueueMovesWakeOnlyWatchersOfQueuedJobs) {
  JobChanges changes;
  const auto queued = changes.Subscribe("job-q");
  const auto running = changes.Subscribe("job-r");
  queued->set_queued(true);
  const int64_t q = queued->version(), r = running->version();
  changes.BumpQueued();
  EXPECT_TRUE(queued->Await(q, kShort));
  EXPECT_FALSE(running->Await(r, kShort));
  queued->set_queued(false);
  const int64_t q2 = queued->version();
  changes.BumpQueued();
  EXPECT_FALSE(queued->Await(q2, kShort));
  changes.BumpAll();
  EXPECT_TRUE(queued->Await(q2, kShort));
  EXPECT_TRUE(running->Await(r, kShort));
}

TEST(JobChanges, SlotsAreSharedAndFreedWithTheLastWatcher) {
  JobChanges changes;
  {
    const auto one = changes.Subscribe("job-a");
    const auto two = changes.Subscribe("job-a");
    const int64_t seen = two->version();
    changes.Bump("job-a");
    EXPECT_TRUE(two->Await(seen, kShort));
    EXPECT_EQ(one->version(), two->version());
    EXPECT_EQ(changes.watched_jobs(), 1);
  }
  EXPECT_EQ(changes.watched_jobs(), 0);
  changes.Bump("job-a");  // no watcher: nothing kept
  EXPECT_EQ(changes.watched_jobs(), 0);
}

}  // namespace
}  // namespace meshseg::server
