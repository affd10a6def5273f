#include <gtest/gtest.h>

#include "server/job_store.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

TEST(WatchJob, ReportsQueuePositionThenEndsInATerminalState) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  ASSERT_TRUE(client.Upload(path).ok());
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));  // the first one runs
  const absl::StatusOr<v1::UploadResponse> second = client.Upload(path);
  ASSERT_TRUE(second.ok()) << second.status();
  EXPECT_EQ(second->queue_position(), 0);
  std::vector<v1::JobEvent> events;
  // The jobs go on only once the watcher has seen the queued state.
  const absl::StatusOr<v1::Job> job = client.Watch(second->job_id(), [&](const v1::JobEvent& e) {
    events.push_back(e);
    if (!gate.open.HasBeenNotified()) gate.open.Notify();
  });
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.front().job().state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(events.front().job().queue_position(), 0);
  EXPECT_FALSE(events.front().message().empty());
  EXPECT_EQ(events.back().job().state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(events.back().job().job_id(), second->job_id());
}

// The gate holds the job for as long as the test wants, so every deadline
// below passes while the job is still QUEUED or RUNNING: no timing matters.
TEST(WatchJob, ExpiredDeadlineIsDeadlineExceededAndTheJobGoesOn) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const absl::StatusOr<v1::UploadResponse> upload = client.Upload(path);
  ASSERT_TRUE(upload.ok()) << upload.status();
  const std::string id = upload->job_id();

  // A deadline that passes while the server streams events (the server's
  // watcher must end the stream itself).
  const absl::StatusOr<v1::Job> watched = client.Watch(id, {}, absl::Milliseconds(200));
  EXPECT_EQ(watched.status().code(), absl::StatusCode::kDeadlineExceeded) << watched.status();
  // A deadline already passed when the call starts. (A zero timeout is not
  // enough: gRPC rounds deadlines up to the millisecond, and a loopback call
  // can finish within it.)
  const absl::Duration passed = -absl::Seconds(1);
  EXPECT_EQ(client.Watch(id, {}, passed).status().code(), absl::StatusCode::kDeadlineExceeded);
  client.set_call_timeout(passed);
  EXPECT_EQ(client.GetJob(id).status().code(), absl::StatusCode::kDeadlineExceeded);
  EXPECT_EQ(client.Cancel(id).status().code(), absl::StatusCode::kDeadlineExceeded);

  client.set_call_timeout(absl::Seconds(10));
  const absl::StatusOr<v1::Job> still = client.GetJob(id);
  ASSERT_TRUE(still.ok()) << still.status();
  EXPECT_FALSE(server::IsTerminal(still->state())) << "an expired call must not end the job";
  gate.open.Notify();
  const absl::StatusOr<v1::Job> done = client.Watch(id);
  ASSERT_TRUE(done.ok()) << done.status();
  EXPECT_EQ(done->state(), v1::JOB_STATE_SUCCEEDED);
}

}  // namespace
}  // namespace meshseg
