#include "server/in_memory_job_queue.h"

#include <thread>

#include <gtest/gtest.h>

namespace meshseg::server {
namespace {

TEST(InMemoryJobQueue, PopsInFifoOrderAndReportsPositions) {
  InMemoryJobQueue q(4);
  ASSERT_TRUE(q.Push("a").ok());
  ASSERT_TRUE(q.Push("b").ok());
  ASSERT_TRUE(q.Push("c").ok());
  EXPECT_EQ(q.Position("c"), 2);
  EXPECT_EQ(q.Position("zz"), -1);
  EXPECT_EQ(q.Pop()->job_id, "a");
  EXPECT_EQ(q.Position("c"), 1);
  EXPECT_TRUE(q.Remove("b"));
  EXPECT_FALSE(q.Remove("b"));
  EXPECT_EQ(q.Pop()->job_id, "c");
  EXPECT_EQ(*q.Size(), 0);
}

TEST(InMemoryJobQueue, RefusesPushesOverCapacity) {
  InMemoryJobQueue q(2);
  ASSERT_TRUE(q.Push("a").ok());
  ASSERT_TRUE(q.Push("b").ok());
  const absl::Status full = q.Push("c");
  EXPECT_EQ(full.code(), absl::StatusCode::kResourceExhausted);
  EXPECT_NE(full.message().find("2 of 2"), absl::string_view::npos) << full;
}

TEST(InMemoryJobQueue, CloseWakesBlockedPops) {
  InMemoryJobQueue q(4);
  std::optional<Lease> popped = Lease{.job_id = "unset", .entry = {}};
  std::thread waiter([&] { popped = q.Pop(); });
  absl::SleepFor(absl::Milliseconds(20));
  q.Close();
  waiter.join();
  EXPECT_FALSE(popped.has_value());
  EXPECT_EQ(q.Push("x").code(), absl::StatusCode::kUnavailable);
}

// Jobs waiting at Close() are not popped; the job store keeps them QUEUED
// for the next start.
TEST(InMemoryJobQueue, ClosedQueuePopsNothing) {
  InMemoryJobQueue q(4);
  ASSERT_TRUE(q.Push("a").ok());
  q.Close();
  EXPECT_FALSE(q.Pop().has_value());
}

// Recovered jobs are queued in their old order even past the capacity.
TEST(InMemoryJobQueue, RestoreAppendsInOrderWhateverTheCapacity) {
  InMemoryJobQueue q(1);
  q.Restore({"a", "b", "c"});
  EXPECT_EQ(q.Position("c"), 2);
  EXPECT_EQ(q.Push("d").code(), absl::StatusCode::kResourceExhausted);
  EXPECT_EQ(q.Pop()->job_id, "a");
  EXPECT_EQ(q.Pop()->job_id, "b");
}

}  // namespace
}  // namespace meshseg::server
