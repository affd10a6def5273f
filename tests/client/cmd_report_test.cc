// meshseg report RESULT.json [MESH] -o REPORT.html, and segment --report:
// the page is written with the geometry and (from segment) the timings; bad
// input exits 1 with one line naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_files::ReadText;
using testing_server::FreshDir;

TEST(MeshsegReport, WritesThePageOfASavedResultWithItsMesh) {
  const std::string dir = FreshDir("files");
  testing_files::WriteOff(testing_files::SplitBox(3, {2.0, 1.0, 0.5}), dir + "/box.off");
  ASSERT_EQ(RunCli({"segment", dir + "/box.off", "-o", dir + "/box.json"}).exit_code, 0);

  const testing_cli::CliRun r =
      RunCli({"report", dir + "/box.json", dir + "/box.off", "-o", dir + "/box.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + dir + "/box.html"));
  const std::string html = ReadText(dir + "/box.html");
  EXPECT_THAT(html, HasSubstr("id=\"meshseg-positions\""));
  EXPECT_THAT(html, HasSubstr("\"title\":\"box.off\""));
  EXPECT_THAT(html, HasSubstr("\"timings\":[]")) << "a saved result has no timings";

  const testing_cli::CliRun tables =
      RunCli({"report", dir + "/box.json", "-o", dir + "/tables.html"});
  ASSERT_EQ(tables.exit_code, 0) << tables.err;
  EXPECT_THAT(ReadText(dir + "/tables.html"), Not(HasSubstr("id=\"meshseg-positions\"")));
}

TEST(MeshsegReport, SegmentWritesTheReportWithTimings) {
  const std::string dir = FreshDir("files");
  testing_files::WriteOff(testing_files::SplitBox(3, {1, 1, 1}), dir + "/box.off");
  const testing_cli::CliRun r =
      RunCli({"segment", dir + "/box.off", "-o", dir + "/box.json", "--report", dir + "/box.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + dir + "/box.html"));
  const std::string html = ReadText(dir + "/box.html");
  EXPECT_THAT(html, HasSubstr("\"stage\":\"segment\""));
  EXPECT_THAT(html, HasSubstr("\"stage\":\"total\""));
  EXPECT_THAT(html, HasSubstr("id=\"meshseg-triangles\""));
}

TEST(MeshsegReport, BadInputExitsOneNamingIt) {
  const std::string dir = FreshDir("files");
  testing_files::WriteText(dir + "/broken.json", "{\"regions\": [");
  testing_files::WriteOff(testing_files::SplitBox(3, {1, 1, 1}), dir + "/box.off");
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), dir + "/other.off");
  ASSERT_EQ(RunCli({"segment", dir + "/box.off", "-o", dir + "/box.json"}).exit_code, 0);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"report", dir + "/broken.json", "-o", dir + "/x.html"}, "broken.json"},
      {{"report", dir + "/missing.json", "-o", dir + "/x.html"}, "missing.json"},
      {{"report", dir + "/box.json", dir + "/other.off", "-o", dir + "/x.html"}, "other.off"},
      {{"report", dir + "/box.json"}, "-o REPORT.html"},
      {{"report", dir + "/box.json", dir + "/box.off", "extra", "-o", dir + "/x.html"},
       "expected 1 to 2 arguments"},
  };
  for (const auto& [args, needle] : cases) {
    const testing_cli::CliRun r = RunCli(args);
    EXPECT_EQ(r.exit_code, 1) << needle;
    EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
    EXPECT_THAT(r.err, HasSubstr(needle));
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.html")) << "no page on error";
}

}  // namespace
}  // namespace meshseg
