// meshseg status JOB --server: the job's state in one line; an unknown job
// exits 1 with one line naming it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_server::FreshDir;
using testing_server::TestServer;

TEST(MeshsegStatus, PrintsTheStateOfAFinishedJobInOneLine) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), dir + "/box.off");
  testing_files::WriteText(dir + "/nan_vertex.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  const std::string good = client.Upload(dir + "/box.off")->job_id();
  const std::string bad = client.Upload(dir + "/nan_vertex.obj")->job_id();
  const absl::StatusOr<v1::Job> done = client.Watch(good);
  ASSERT_TRUE(done.ok()) << done.status();
  ASSERT_EQ(client.Watch(bad)->state(), v1::JOB_STATE_FAILED);

  const testing_cli::CliRun ok = RunCli({"status", good, "--server", server.address()});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.err, "");
  ASSERT_THAT(Lines(ok.out), SizeIs(1)) << ok.out;
  EXPECT_THAT(ok.out, ::testing::StartsWith(good));
  EXPECT_THAT(ok.out, HasSubstr("SUCCEEDED"));
  EXPECT_THAT(ok.out, HasSubstr("box.off"));
  EXPECT_THAT(ok.out, HasSubstr(absl::StrCat(done->region_count(), " regions, 48 faces")));

  // Reporting a failed job is a successful command.
  const testing_cli::CliRun failed = RunCli({"status", bad, "--server", server.address()});
  ASSERT_EQ(failed.exit_code, 0) << failed.err;
  ASSERT_THAT(Lines(failed.out), SizeIs(1)) << failed.out;
  EXPECT_THAT(failed.out, HasSubstr("FAILED"));
  EXPECT_THAT(failed.out, HasSubstr("nan_vertex.obj"));
}

TEST(MeshsegStatus, UnknownJobExitsOneWithOneLineNamingIt) {
  TestServer server;
  const testing_cli::CliRun r =
      RunCli({"status", "job-0000feedbeef", "--server", server.address()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("job-0000feedbeef"));
  EXPECT_THAT(r.err, HasSubstr("not found"));
}

}  // namespace
}  // namespace meshseg
