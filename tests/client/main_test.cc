// meshseg's dispatcher: exit codes and the one-line error contract.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/client/run_cli.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;

TEST(MeshsegMain, UnknownCommandExitsTwoWithOneLine) {
  const testing_cli::CliRun r = RunCli({"segmnet", "part.stl"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("segmnet"));
  EXPECT_EQ(r.out, "");
}

TEST(MeshsegMain, NoCommandExitsTwoWithUsageAndHelpExitsZero) {
  const testing_cli::CliRun none = RunCli({});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("usage: meshseg"));
  const testing_cli::CliRun help = RunCli({"help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.out, HasSubstr("reconstruct CLOUD"));
}

TEST(MeshsegMain, BadOptionExitsOneWithOneLine) {
  const testing_cli::CliRun r = RunCli({"info", "x.off", "--frobnicate"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--frobnicate"));
}

TEST(MeshsegMain, JobCommandWithoutServerSaysHowToGiveOne) {
  const testing_cli::CliRun r = RunCli({"jobs"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--server"));
}

}  // namespace
}  // namespace meshseg
