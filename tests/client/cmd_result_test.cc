// meshseg result JOB -o FILE --server: writes the JSON `meshseg segment`
// writes for the same input (offline and --server), byte for byte; a job
// without a result exits 1 and writes no file.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::SizeIs;
using testing_cli::Lines;
using testing_cli::RunCli;
using testing_files::ReadText;
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

// A generated part with several regions (plate_boss, coarse voxels).
TEST(MeshsegResult, WritesTheSegmentJsonByteForByte) {
  TestServer server;
  const std::string dir = FreshDir("files");
  const std::string part = dir + "/plate_boss.ply";
  const testing_cli::CliRun gen =
      RunCli({"generate", "plate_boss", "-o", part, "--voxel-size", "1.5"});
  ASSERT_EQ(gen.exit_code, 0) << gen.err;
  const testing_cli::CliRun offline =
      RunCli({"segment", part, "-o", dir + "/offline.json", "--distance-tolerance", "0.7"});
  ASSERT_EQ(offline.exit_code, 0) << offline.err;

  MeshsegClient client = server.Client();
  UploadOptions options;
  options.segment.set_distance_tolerance(0.7);
  const absl::StatusOr<v1::UploadResponse> up = client.Upload(part, options);
  ASSERT_TRUE(up.ok()) << up.status();
  ASSERT_EQ(client.Watch(up->job_id())->state(), v1::JOB_STATE_SUCCEEDED);

  const std::string out = dir + "/result.json";
  const testing_cli::CliRun r =
      RunCli({"result", up->job_id(), "-o", out, "--server", server.address()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_THAT(r.out, HasSubstr("regions cover"));
  EXPECT_THAT(r.out, HasSubstr("wrote " + out));
  // The boundary and feature summary after the table (issue 5 item 5).
  EXPECT_THAT(r.out, ::testing::ContainsRegex(
                         "boundaries: [1-9][0-9]* curves \\([^)]*line[^)]*\\), [1-9][0-9]* loops"));
  EXPECT_THAT(r.out, HasSubstr("fillet_torus_cylinder_plane  regions "));
  EXPECT_THAT(r.out, HasSubstr("revolution "));
  const std::string json = ReadText(out);
  const std::string expected = ReadText(dir + "/offline.json");
  EXPECT_GT(testing_cli::ParseJsonObject(json).fields().at("regions").list_value().values_size(), 3)
      << "several regions";
  EXPECT_EQ(json, expected) << "result = offline segment";
  // The region table, after segment's progress lines.
  const std::size_t summary = offline.out.rfind('\n', offline.out.find(" regions cover ")) + 1;
  EXPECT_THAT(r.out, HasSubstr(offline.out.substr(summary, offline.out.find("wrote ") - summary)))
      << "the same region table";

  const testing_cli::CliRun remote =
      RunCli({"segment", part, "-o", dir + "/server.json", "--distance-tolerance", "0.7",
              "--server", server.address()});
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_EQ(json, ReadText(dir + "/server.json")) << "result = segment --server";
}

TEST(MeshsegResult, JobWithoutResultExitsOneAndWritesNothing) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), dir + "/box.off");
  const std::string running = client.Upload(dir + "/box.off")->job_id();
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));
  const std::string out = dir + "/never.json";

  const testing_cli::CliRun early =
      RunCli({"result", running, "-o", out, "--server", server.address()});
  EXPECT_EQ(early.exit_code, 1);
  EXPECT_THAT(Lines(early.err), SizeIs(1)) << early.err;
  EXPECT_THAT(early.err, HasSubstr(running));
  EXPECT_THAT(early.err, HasSubstr("RUNNING"));

  const testing_cli::CliRun unknown =
      RunCli({"result", "job-0000feedbeef", "-o", out, "--server", server.address()});
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_THAT(Lines(unknown.err), SizeIs(1)) << unknown.err;
  EXPECT_THAT(unknown.err, HasSubstr("job-0000feedbeef"));

  const testing_cli::CliRun no_out = RunCli({"result", running, "--server", server.address()});
  EXPECT_EQ(no_out.exit_code, 1);
  EXPECT_THAT(no_out.err, HasSubstr("-o"));
  EXPECT_FALSE(std::filesystem::exists(out));
  gate.open.Notify();
}

}  // namespace
}  // namespace meshseg
