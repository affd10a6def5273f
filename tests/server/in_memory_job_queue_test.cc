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
  EXPECT_EQ(*q.Pop(), "a");
  EXPECT_EQ(q.Position("c"), 1);
  EXPECT_TRUE(q.Remove("b"));
  EXPECT_FALSE(q.Remove("b"));
  EXPECT_EQ(*q.Pop(), "c");
  EXPECT_EQ(q.Size(), 0);
}

TEST(InMemoryJobQueue, RefusesPushesOverCapacity) {
  InMemoryJobQueue q(2);
  ASSERT_TRUE(q.Push("a").ok());
  ASSERT_TRUE(q.Push("b").ok());
  const absl::Status full = q.Push("c");
  EXPECT_EQ(full.code(), absl::StatusCode::kResourceExhausted);
  EXPECT_NE(full.message().find("2 of 2"), absl::string_view::npos) << full;
}

TEST(InMemoryJobQueue, CloseWakesBlockedPopsAndReturnsWaitingIds) {
  InMemoryJobQueue q(4);
  std::optional<std::string> popped = "unset";
  std::thread waiter([&] { popped = q.Pop(); });
  absl::SleepFor(absl::Milliseconds(20));
  EXPECT_TRUE(q.Close().empty());
  waiter.join();
  EXPECT_FALSE(popped.has_value());
  EXPECT_EQ(q.Push("x").code(), absl::StatusCode::kUnavailable);
}

TEST(InMemoryJobQueue, CloseHandsBackQueuedIds) {
  InMemoryJobQueue q(4);
  ASSERT_TRUE(q.Push("a").ok());
  ASSERT_TRUE(q.Push("b").ok());
  EXPECT_EQ(q.Close(), (std::vector<std::string>{"a", "b"}));
  EXPECT_FALSE(q.Pop().has_value());
}

}  // namespace
}  // namespace meshseg::server
