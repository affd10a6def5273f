#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

class CancelJobTest : public ::testing::Test {
 protected:
  CancelJobTest() : server_({.workers = 1, .runner = gate_.Runner()}) {
    path_ = FreshDir("files") + "/box.off";
    testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path_);
  }
  Gate gate_;
  TestServer server_;
  std::string path_;
};

TEST_F(CancelJobTest, CancelMidRunStopsTheJobPromptlyAndFreesItsWorker) {
  MeshsegClient client = server_.Client();
  const std::string running = client.Upload(path_)->job_id();
  const std::string next = client.Upload(path_)->job_id();
  ASSERT_TRUE(Eventually([&] { return client.GetJob(running)->state() == v1::JOB_STATE_RUNNING; }));
  const absl::Time start = absl::Now();
  ASSERT_TRUE(client.Cancel(running).ok());
  const absl::StatusOr<v1::Job> job = client.Watch(running, {}, absl::Seconds(10));
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_LT(absl::Now() - start, absl::Seconds(5)) << "cancel must be prompt";
  // The single worker moves on to the next job.
  ASSERT_TRUE(Eventually([&] { return gate_.entered == 2; }));
  gate_.open.Notify();
  EXPECT_EQ(client.Watch(next)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(server_.SpoolFiles(), 1) << "only the finished job's result";
}

TEST_F(CancelJobTest, CancelQueuedJobNeverRunsIt) {
  MeshsegClient client = server_.Client();
  const std::string running = client.Upload(path_)->job_id();
  const std::string queued = client.Upload(path_)->job_id();
  const absl::StatusOr<v1::Job> job = client.Cancel(queued);
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  gate_.open.Notify();
  EXPECT_EQ(client.Watch(running)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(gate_.entered, 1);
  EXPECT_EQ(client.Cancel(running).status().code(), absl::StatusCode::kFailedPrecondition);
}

TEST_F(CancelJobTest, UnknownJobIsNotFound) {
  MeshsegClient client = server_.Client();
  EXPECT_EQ(client.Cancel("job-0000000000000000").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.GetJob("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Result("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Watch("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(std::string(client.GetJob("nope").status().message()),
              ::testing::HasSubstr("nope"));
  gate_.open.Notify();
}

}  // namespace
}  // namespace meshseg
