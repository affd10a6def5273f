// Progress as a person sees it: a bar redrawn in place on a terminal, plain
// "progress:" lines on stdout otherwise (offline and through a server).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "absl/synchronization/notification.h"
#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing_cli::RunCli;
using testing_cli::RunCliOnTerminal;
using testing_server::FreshDir;
using testing_server::TestServer;

// The whole-job percentages after each `marker` in `out` ("(job 43%").
std::vector<int> JobPercents(const std::string& out, const std::string& marker) {
  std::vector<int> percents;
  for (std::size_t at = out.find(marker); at != std::string::npos; at = out.find(marker, at + 1)) {
    percents.push_back(std::atoi(out.c_str() + at + marker.size()));
  }
  return percents;
}

// The server's jobs stop at their first "segment" report until the test has
// seen the client print that stage: a job on loopback can otherwise end
// before the client's watch starts, and then there is no progress to show.
class ProgressTest : public ::testing::Test {
 protected:
  ProgressTest() : server_({.runner = HeldAtSegment()}), dir_(FreshDir("files")) {
    testing_files::WriteOff(testing_files::SplitBox(3, {1, 1, 1}), dir_ + "/box.off");
  }
  std::vector<std::string> Segment(const std::vector<std::string>& extra) const {
    std::vector<std::string> args = {"segment", dir_ + "/box.off", "-o", dir_ + "/box.json"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
  server::JobRunner HeldAtSegment() {
    return [this](const std::string& path, const PipelineParams& params, const RunContext& ctx) {
      RunContext inner = ctx;
      inner.on_progress = [&](std::string_view stage, double fraction) {
        ctx.Progress(stage, fraction);
        if (stage != "segment") return;
        while (!seen_.WaitForNotificationWithTimeout(absl::Milliseconds(5))) {
          if (ctx.stop_requested()) return;
        }
      };
      return RunPipeline(path, params, inner);
    };
  }
  // Opens the held job once `needle` is in the client's output.
  testing_cli::OnOutput ReleaseOn(const std::string& needle) {
    return [this, needle](const std::string& so_far) {
      if (so_far.find(needle) != std::string::npos && !seen_.HasBeenNotified()) seen_.Notify();
    };
  }

  absl::Notification seen_;
  TestServer server_;
  std::string dir_;
};

TEST_F(ProgressTest, PlainLinesWhenNotATerminal) {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{}, std::vector<std::string>{"--server", server_.address()}}) {
    const bool server = !extra.empty();  // only the server's job is held
    const testing_cli::CliRun r =
        RunCli(Segment(extra), server ? ReleaseOn("progress: segment") : nullptr);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("progress: segment"));
    EXPECT_THAT(r.out, Not(HasSubstr("\r"))) << "no carriage returns in a log";
    const std::vector<int> job = JobPercents(r.out, "(job ");
    ASSERT_FALSE(job.empty()) << r.out;
    EXPECT_TRUE(std::is_sorted(job.begin(), job.end())) << "the job's share never goes back\n"
                                                        << r.out;
    EXPECT_EQ(job.back(), 100) << r.out;
    EXPECT_THAT(r.out, HasSubstr("ETA "));
    EXPECT_EQ(r.err, "");
  }
}

TEST_F(ProgressTest, BarRedrawnInPlaceOnATerminal) {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{}, std::vector<std::string>{"--server", server_.address()}}) {
    const bool server = !extra.empty();  // only the server's job is held
    const testing_cli::CliRun r =
        RunCliOnTerminal(Segment(extra), server ? ReleaseOn("] segment") : nullptr);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("\r[")) << "the bar starts each redraw at column 0";
    EXPECT_THAT(r.out, HasSubstr("] segment"));
    EXPECT_THAT(r.out, HasSubstr("100%"));
    EXPECT_THAT(r.out, Not(HasSubstr("progress: "))) << "no plain lines on a terminal";
    EXPECT_THAT(r.out, HasSubstr("job 100%  ETA 0:00"));
  }
}

}  // namespace
}  // namespace meshseg
