#include "server/job_store.h"

#include <gtest/gtest.h>

#include "server/in_memory_job_queue.h"

namespace meshseg::server {
namespace {

class JobStoreTest : public ::testing::Test {
 protected:
  std::string AddQueued() {
    const std::string id = store_.NewId();
    store_.Add(id, "part.stl", 100, "/spool/" + id + "/part.stl", {});
    EXPECT_TRUE(queue_.Push(id).ok());
    return id;
  }
  InMemoryJobQueue queue_{8};
  JobStore store_{queue_};
};

TEST_F(JobStoreTest, WalksQueuedRunningSucceeded) {
  const std::string id = AddQueued();
  EXPECT_EQ(store_.Get(id)->state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(store_.Get(id)->queue_position(), 0);
  ASSERT_EQ(*queue_.Pop(), id);
  const std::optional<RunSpec> spec = store_.Start(id);
  ASSERT_TRUE(spec.has_value());
  EXPECT_EQ(spec->input_path, "/spool/" + id + "/part.stl");
  store_.Progress(id, "read", 0.5);
  EXPECT_EQ(store_.Get(id)->stage(), "read");
  EXPECT_EQ(store_.Get(id)->queue_position(), -1);
  store_.Finish(id, absl::OkStatus(), 42, 12, 3);
  const v1::Job job = *store_.Get(id);
  EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(job.result_size(), 42);
  EXPECT_EQ(job.region_count(), 3);
  EXPECT_GT(job.finished_unix_ms(), 0);
}

TEST_F(JobStoreTest, FailedJobKeepsCodeAndMessage) {
  const std::string id = AddQueued();
  ASSERT_TRUE(store_.Start(id).has_value());
  store_.Finish(id, absl::InvalidArgumentError("read_mesh: \"x.stl\": nan"), 0, 0, 0);
  const v1::Job job = *store_.Get(id);
  EXPECT_EQ(job.state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(job.error_code(), static_cast<int>(absl::StatusCode::kInvalidArgument));
  EXPECT_EQ(job.error_message(), "read_mesh: \"x.stl\": nan");
}

TEST_F(JobStoreTest, CancelQueuedIsImmediateAndRunningRequestsStop) {
  const std::string queued = AddQueued();
  const std::string running = AddQueued();
  ASSERT_TRUE(store_.Start(running).has_value());
  EXPECT_EQ(*store_.Cancel(queued, "bye"), JobStore::CancelOutcome::kWasQueued);
  EXPECT_EQ(store_.Get(queued)->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_FALSE(store_.Start(queued).has_value()) << "a cancelled job must not run";
  EXPECT_EQ(*store_.Cancel(running, "bye"), JobStore::CancelOutcome::kStopRequested);
  store_.Finish(running, absl::CancelledError("stopped"), 0, 0, 0);
  EXPECT_EQ(store_.Get(running)->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(store_.Cancel(running, "again").status().code(),
            absl::StatusCode::kFailedPrecondition);
}

TEST_F(JobStoreTest, StartHandsOutTheJobsStopToken) {
  const std::string id = AddQueued();
  const std::optional<RunSpec> spec = store_.Start(id);
  ASSERT_TRUE(spec.has_value());
  EXPECT_FALSE(spec->stop.stop_requested());
  ASSERT_TRUE(store_.Cancel(id, "stop").ok());
  EXPECT_TRUE(spec->stop.stop_requested());
}

TEST_F(JobStoreTest, UnknownIdIsNotFound) {
  EXPECT_EQ(store_.Get("job-nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(store_.Cancel("job-nope", "x").status().code(), absl::StatusCode::kNotFound);
}

TEST_F(JobStoreTest, ExpireForgetsOnlyFinishedJobsOlderThanTheCutoff) {
  const std::string done = AddQueued();
  const std::string waiting = AddQueued();
  ASSERT_TRUE(store_.Start(done).has_value());
  store_.Finish(done, absl::OkStatus(), 1, 1, 1);
  EXPECT_TRUE(store_.Expire(absl::Now() - absl::Hours(1)).empty());
  EXPECT_EQ(store_.Expire(absl::Now() + absl::Seconds(1)), std::vector<std::string>{done});
  EXPECT_EQ(store_.Get(done).status().code(), absl::StatusCode::kNotFound);
  EXPECT_TRUE(store_.Get(waiting).ok());
}

TEST_F(JobStoreTest, GenerationGrowsOnEveryChange) {
  const int64_t before = store_.generation();
  const std::string id = AddQueued();
  EXPECT_GT(store_.generation(), before);
  const int64_t after_add = store_.generation();
  ASSERT_TRUE(store_.Start(id).has_value());
  store_.AwaitChange(after_add, absl::Seconds(5));  // returns at once
  EXPECT_GT(store_.generation(), after_add);
}

}  // namespace
}  // namespace meshseg::server
