// meshseg watch JOB --server: plain progress lines (stdout is not a
// terminal) until the job ends, then its line; a job that does not succeed
// exits 1 with its error in one line.
#include <array>
#include <atomic>
#include <mutex>
#include <thread>

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
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::TestServer;

// A watch samples the job's latest state, so each state it must print is
// held until it has been printed: job 0 holds the only worker until watch
// shows job 1 queued; job 1 then stops at "segment 50%" until watch shows
// that, and runs the real pipeline.
TEST(MeshsegWatch, PrintsProgressFromQueuedToSucceeded) {
  std::array<absl::Notification, 2> release;
  std::array<std::once_flag, 2> once;
  const auto open = [&](int n) { std::call_once(once[n], [&] { release[n].Notify(); }); };
  std::atomic<int> entered{0};
  const server::JobRunner runner = [&](const std::string& path, const PipelineParams& params,
                                       const RunContext& ctx) -> absl::StatusOr<PipelineResult> {
    const int n = entered++;
    ctx.Progress("segment", 0.5);
    while (!release[n].WaitForNotificationWithTimeout(absl::Milliseconds(5))) {
      if (ctx.stop_requested()) return absl::CancelledError("test: stop requested");
    }
    return RunPipeline(path, params, ctx);
  };
  TestServer server({.workers = 1, .runner = runner});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  ASSERT_TRUE(client.Upload(path).ok());
  const std::string watched = client.Upload(path)->job_id();
  ASSERT_TRUE(Eventually([&] { return entered == 1; }));

  // A broken watch cannot hang the test: everything is released after 10 s.
  absl::Notification finished;
  std::thread fallback([&] {
    finished.WaitForNotificationWithTimeout(absl::Seconds(10));
    open(0);
    open(1);
  });
  const testing_cli::CliRun r =
      RunCli({"watch", watched, "--server", server.address()}, [&](const std::string& so_far) {
        if (so_far.find("progress: queued 0%") != std::string::npos) open(0);
        if (so_far.find("progress: segment 50%") != std::string::npos) open(1);
      });
  finished.Notify();
  fallback.join();

  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> lines = Lines(r.out);
  ASSERT_GE(lines.size(), 3u) << r.out;
  EXPECT_THAT(lines[0], StartsWith("progress: queued 0% (job 0%, ETA ")) << r.out;
  EXPECT_THAT(lines[1], StartsWith("progress: segment 50% (job ")) << r.out;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    EXPECT_THAT(lines[i], StartsWith("progress: ")) << "plain lines, no bar";
  }
  EXPECT_THAT(lines.back(), StartsWith(watched));
  EXPECT_THAT(lines.back(), HasSubstr("SUCCEEDED"));
  EXPECT_THAT(lines.back(), HasSubstr("48 faces"));
}

TEST(MeshsegWatch, FailedJobExitsOneWithItsErrorInOneLine) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/nan_vertex.obj";
  testing_files::WriteText(path, "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  const std::string id = client.Upload(path)->job_id();
  const testing_cli::CliRun r = RunCli({"watch", id, "--server", server.address()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr(id));
  EXPECT_THAT(r.err, HasSubstr("FAILED"));
  EXPECT_THAT(r.err, HasSubstr("nan_vertex.obj"));
}

TEST(MeshsegWatch, UnknownJobExitsOneNamingIt) {
  TestServer server;
  const testing_cli::CliRun r = RunCli({"watch", "job-0000feedbeef", "--server", server.address()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("job-0000feedbeef"));
}

}  // namespace
}  // namespace meshseg
