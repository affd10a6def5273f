// meshseg cancel JOB --server: a running job stops (status then says
// CANCELLED), a queued one is cancelled at once; a finished or unknown job
// exits 1 with one line naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::SizeIs;
using ::testing::StartsWith;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::RunningAndQueued;
using testing_server::TestServer;
using testing_server::UploadRunningAndQueued;

TEST(MeshsegCancel, StopsARunningJobAndCancelsAQueuedOne) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  const absl::StatusOr<RunningAndQueued> jobs = UploadRunningAndQueued(client, gate, path);
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  const std::string& running = jobs->running;
  const std::string& queued = jobs->queued;

  const testing_cli::CliRun q = RunCli({"cancel", queued, "--server", server.address()});
  ASSERT_EQ(q.exit_code, 0) << q.err;
  ASSERT_THAT(Lines(q.out), SizeIs(1)) << q.out;
  EXPECT_THAT(q.out, StartsWith(queued));
  EXPECT_THAT(q.out, HasSubstr("CANCELLED"));

  const testing_cli::CliRun r = RunCli({"cancel", running, "--server", server.address()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_THAT(Lines(r.out), SizeIs(1)) << r.out;
  EXPECT_THAT(r.out, StartsWith(running));
  const absl::StatusOr<v1::Job> stopped = client.Watch(running);
  ASSERT_TRUE(stopped.ok()) << stopped.status();
  EXPECT_EQ(stopped->state(), v1::JOB_STATE_CANCELLED);
  const testing_cli::CliRun status = RunCli({"status", running, "--server", server.address()});
  ASSERT_EQ(status.exit_code, 0) << status.err;
  EXPECT_THAT(status.out, HasSubstr("CANCELLED"));
  EXPECT_EQ(gate.entered, 1) << "the queued job never ran";
}

TEST(MeshsegCancel, FinishedOrUnknownJobExitsOneNamingIt) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  const std::string done = client.Upload(path)->job_id();
  ASSERT_EQ(client.Watch(done)->state(), v1::JOB_STATE_SUCCEEDED);
  for (const std::string& id : {done, std::string("job-0000feedbeef")}) {
    const testing_cli::CliRun r = RunCli({"cancel", id, "--server", server.address()});
    EXPECT_EQ(r.exit_code, 1) << id;
    EXPECT_EQ(r.out, "") << id;
    EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
    EXPECT_THAT(r.err, HasSubstr(id));
  }
  const testing_cli::CliRun still = RunCli({"status", done, "--server", server.address()});
  EXPECT_THAT(still.out, HasSubstr("SUCCEEDED")) << "a refused cancel changes nothing";
}

}  // namespace
}  // namespace meshseg
