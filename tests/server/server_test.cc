// The server as a whole: health, graceful shutdown, result expiry.
#include <gtest/gtest.h>

#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::HealthStatus;
using testing_server::TestServer;

TEST(Server, ListensOnAnEphemeralPortAndIsServing) {
  TestServer server;
  EXPECT_GT(server.server().port(), 0);
  EXPECT_EQ(HealthStatus(server.address()), 1);
}

TEST(Server, HealthStaysServingAfterBadInput) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/broken.off";
  testing_files::WriteText(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_FALSE(client.Segment(path).ok());
  EXPECT_EQ(HealthStatus(server.address()), 1);
}

TEST(Server, ShutdownLetsRunningJobsFinishAndCancelsQueuedOnes) {
  Gate gate;
  TestServer server({.workers = 1, .shutdown_grace = absl::Seconds(10), .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string running = client.Upload(path)->job_id();
  const std::string queued = client.Upload(path)->job_id();
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));
  std::thread stopper([&] { server.server().Shutdown(); });
  ASSERT_TRUE(Eventually([&] { return HealthStatus(server.address()) == 2; }));
  EXPECT_EQ(client.Upload(path).status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(client.GetJob(queued)->state(), v1::JOB_STATE_CANCELLED);
  gate.open.Notify();  // the running job finishes within the grace period
  EXPECT_EQ(client.Watch(running)->state(), v1::JOB_STATE_SUCCEEDED);
  stopper.join();
}

TEST(Server, ShutdownCancelsRunningJobsAfterTheGracePeriod) {
  Gate gate;
  TestServer server(
      {.workers = 1, .shutdown_grace = absl::Milliseconds(200), .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string running = client.Upload(path)->job_id();
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));
  absl::StatusOr<v1::Job> watched;
  std::thread watcher([&] { watched = client.Watch(running); });
  server.server().Shutdown();
  watcher.join();
  ASSERT_TRUE(watched.ok()) << watched.status();
  EXPECT_EQ(watched->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(server.SpoolFiles(), 0);
}

TEST(Server, FinishedJobsExpireAfterTheirTtl) {
  TestServer server({.result_ttl = absl::Milliseconds(300)});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  ASSERT_EQ(client.Watch(id)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(
      Eventually([&] { return client.GetJob(id).status().code() == absl::StatusCode::kNotFound; }));
  EXPECT_EQ(server.SpoolFiles(), 0);
}

}  // namespace
}  // namespace meshseg
