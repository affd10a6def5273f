// Progress as a person sees it: a bar redrawn in place on a terminal, plain
// "progress:" lines on stdout otherwise (offline and through a server).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
  }
}

}  // namespace
}  // namespace meshseg
