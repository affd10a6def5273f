#include <gtest/gtest.h>

#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

TEST(WatchJob, ReportsQueuePositionThenEndsInATerminalState) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  client.Upload(path);
  const absl::StatusOr<v1::UploadResponse> second = client.Upload(path);
  ASSERT_TRUE(second.ok());
  std::vector<v1::JobEvent> events;
  std::thread opener([&] {
    absl::SleepFor(absl::Milliseconds(200));
    gate.open.Notify();
  });
  const absl::StatusOr<v1::Job> job =
      client.Watch(second->job_id(), [&](const v1::JobEvent& e) { events.push_back(e); });
  opener.join();
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.front().job().state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(events.front().job().queue_position(), 0);
  EXPECT_FALSE(events.front().message().empty());
  EXPECT_EQ(events.back().job().state(), v1::JOB_STATE_SUCCEEDED);
}

TEST(WatchJob, ExpiredDeadlineIsDeadlineExceededAndTheJobGoesOn) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::Job> watched = client.Watch(id, {}, absl::Milliseconds(300));
  EXPECT_EQ(watched.status().code(), absl::StatusCode::kDeadlineExceeded) << watched.status();
  client.set_call_timeout(absl::ZeroDuration());
  EXPECT_EQ(client.GetJob(id).status().code(), absl::StatusCode::kDeadlineExceeded);
  client.set_call_timeout(absl::Seconds(10));
  gate.open.Notify();
  EXPECT_EQ(client.Watch(id)->state(), v1::JOB_STATE_SUCCEEDED);
}

}  // namespace
}  // namespace meshseg
