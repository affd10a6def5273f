// meshseg jobs --server: one line per job the server knows, with its state.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::RunningAndQueued;
using testing_server::TestServer;
using testing_server::UploadRunningAndQueued;

TEST(MeshsegJobs, ListsEveryJobOnOneLineWithItsState) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  const absl::StatusOr<RunningAndQueued> jobs = UploadRunningAndQueued(client, gate, path);
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  const std::string& running = jobs->running;
  const std::string& queued = jobs->queued;

  const testing_cli::CliRun during = RunCli({"jobs", "--server", server.address()});
  ASSERT_EQ(during.exit_code, 0) << during.err;
  EXPECT_EQ(during.err, "");
  EXPECT_THAT(Lines(during.out), SizeIs(2)) << during.out;
  EXPECT_THAT(Lines(during.out),
              Contains(AllOf(HasSubstr(running), HasSubstr("RUNNING"), HasSubstr("box.off"))));
  EXPECT_THAT(Lines(during.out), Contains(AllOf(HasSubstr(queued), HasSubstr("QUEUED"),
                                                HasSubstr("box.off"), HasSubstr("ahead"))));

  gate.open.Notify();
  ASSERT_EQ(client.Watch(queued)->state(), v1::JOB_STATE_SUCCEEDED);
  const testing_cli::CliRun after = RunCli({"jobs", "--server", server.address()});
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_THAT(Lines(after.out), SizeIs(2)) << after.out;
  for (const std::string& id : {running, queued}) {
    EXPECT_THAT(Lines(after.out),
                Contains(AllOf(HasSubstr(id), HasSubstr("SUCCEEDED"), HasSubstr("48 faces"))));
  }
}

TEST(MeshsegJobs, EmptyServerSaysNoJobs) {
  TestServer server;
  const testing_cli::CliRun r = RunCli({"jobs", "--server", server.address()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "no jobs\n");
}

}  // namespace
}  // namespace meshseg
