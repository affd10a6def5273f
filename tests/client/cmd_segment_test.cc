// meshseg segment: offline writes the result JSON with one label per input
// face; with --server the same bytes come from a real server on 127.0.0.1;
// point clouds work on both paths; errors are one line and exit code 1.
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "meshseg/v1/segmentation.pb.h"
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
using testing_server::TestServer;

v1::SegmentationResult ParseResult(const std::string& json) {
  v1::SegmentationResult result;
  const auto status = google::protobuf::util::JsonStringToMessage(json, &result);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return result;
}

TEST(MeshsegSegment, OfflineWritesValidJsonWithOneLabelPerInputFace) {
  const std::string dir = FreshDir("files");
  testing_files::TestMesh box = testing_files::SplitBox(3, {2.0, 1.0, 0.5});
  const int kept = static_cast<int>(box.f.size());
  box.f.push_back({0, 0, 1});  // degenerate: dropped while loading, label -1
  const std::string path = dir + "/box.off";
  testing_files::WriteOff(box, path);
  const testing_cli::CliRun r = RunCli({"segment", path, "-o", dir + "/box.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "stderr is for errors; progress is on stdout when not a terminal";
  EXPECT_THAT(r.out, HasSubstr("wrote " + dir + "/box.json"));
  const v1::SegmentationResult result = ParseResult(ReadText(dir + "/box.json"));
  ASSERT_EQ(result.face_labels_size(), kept + 1);
  EXPECT_EQ(result.face_labels(kept), -1);
  EXPECT_EQ(result.mesh().face_count(), kept + 1) << "faces as read from the file";
  ASSERT_GE(result.regions_size(), 1);
  for (int i = 0; i < kept; ++i) {
    ASSERT_GE(result.face_labels(i), 0) << "face " << i;
    ASSERT_LT(result.face_labels(i), result.regions_size()) << "face " << i;
  }
  // The contract's spelling: snake_case names, enums as names.
  const std::string json = ReadText(dir + "/box.json");
  EXPECT_THAT(json, HasSubstr("\"face_labels\""));
  EXPECT_THAT(json, HasSubstr("\"type\":\"SURFACE_TYPE_"));
}

TEST(MeshsegSegment, BadFileExitsOneWithOneLineNamingIt) {
  const std::string dir = FreshDir("files");
  const std::string path = dir + "/nan_vertex.obj";
  testing_files::WriteText(path, "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  const std::string out = dir + "/never.json";
  for (const std::string& input : {path, dir + "/missing.stl"}) {
    const testing_cli::CliRun r = RunCli({"segment", input, "-o", out});
    EXPECT_EQ(r.exit_code, 1) << input;
    EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
    EXPECT_THAT(r.err, HasSubstr(std::filesystem::path(input).filename().string()));
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "no result file on error";
}

TEST(MeshsegSegment, BadToleranceExitsOneBeforeReadingTheFile) {
  const testing_cli::CliRun r =
      RunCli({"segment", "/nonexistent.stl", "-o", "/tmp/x.json", "--angle-tolerance", "-3"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("-3"));
}

// Issue 35: the freeform-fit options are checked before the file is read.
TEST(MeshsegSegment, BadFreeformOptionsExitOneBeforeReadingTheFile) {
  for (const auto& [flag, value, message] :
       std::vector<std::array<std::string, 3>>{
           {"--freeform-fit", "maybe", "--freeform-fit must be on or off, got \"maybe\""},
           {"--freeform-fraction", "0.5", "freeform_face_fraction must be in (0, 0.25], got 0.5"}}) {
    const testing_cli::CliRun r =
        RunCli({"segment", "/nonexistent.stl", "-o", "/tmp/x.json", flag, value});
    EXPECT_EQ(r.exit_code, 1) << flag;
    EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
    EXPECT_THAT(r.err, HasSubstr(message));
  }
}

// Issue 38: a cloud with an unscanned area says which faces close it; with
// --open (both paths: the option travels in SegmentOptions) none is filled
// and the mesh is open there.
TEST(MeshsegSegment, FilledFacesOfACloudAreFlaggedAndOpenLeavesThemOut) {
  TestServer server;
  const std::string dir = FreshDir("files");
  testing_files::TestMesh box = testing_files::SplitBox(16, {2.0, 1.5, 1.0});
  std::erase_if(box.v, [](const Eigen::Vector3d& p) {
    return p.z() == 1.0 && p.x() > 0.25 && p.x() < 1.75 && p.y() > 0.25 && p.y() < 1.25;
  });
  testing_files::WriteXyz(box, dir + "/open_top.xyz");
  testing_cli::CliRun r = RunCli({"segment", dir + "/open_top.xyz", "-o", dir + "/closed.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  v1::SegmentationResult result = ParseResult(ReadText(dir + "/closed.json"));
  ASSERT_EQ(result.face_filled_size(), result.face_labels_size());
  int64_t filled = 0;
  for (const bool f : result.face_filled()) filled += f;
  EXPECT_GT(filled, 0);
  EXPECT_EQ(result.mesh().filled_face_count(), filled);
  // The patch spans the unscanned 1.5 x 1.0 rectangle inset by the support
  // reach on every side (2 local spacings of ~0.13 plus the noise band of
  // ~0.1: ~0.35), about (1.5 - 0.7) x (1.0 - 0.7) = 0.24; never more than the
  // flat rectangle.
  EXPECT_GT(result.mesh().filled_area(), 0.15);
  EXPECT_LT(result.mesh().filled_area(), 1.5 * 1.0);
  EXPECT_EQ(result.mesh().boundary_edge_count(), 0);

  for (const bool on_server : {false, true}) {
    std::vector<std::string> args = {"segment", dir + "/open_top.xyz", "-o", dir + "/open.json",
                                     "--open"};
    if (on_server) args.insert(args.end(), {"--server", server.address()});
    r = RunCli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    result = ParseResult(ReadText(dir + "/open.json"));
    EXPECT_EQ(result.mesh().filled_face_count(), 0) << on_server;
    EXPECT_GE(result.mesh().boundary_edge_count(), 8) << on_server;  // the loop round the hole
    for (const bool f : result.face_filled()) EXPECT_FALSE(f);
  }
}

TEST(MeshsegSegment, ServerPathWritesTheOfflineBytes) {
  TestServer server;
  const std::string dir = FreshDir("files");
  const testing_files::TestMesh box = testing_files::SplitBox(4, {2.0, 1.0, 0.5});
  testing_files::WriteStlBinary(box, dir + "/box.stl");
  testing_files::WriteXyz(testing_files::SplitBox(16, {2.0, 1.5, 1.0}), dir + "/cloud.xyz");
  for (const std::string name : {"box.stl", "cloud.xyz"}) {
    const std::string input = dir + "/" + name;
    const std::vector<std::string> tol = {"--distance-tolerance", "0.7"};
    testing_cli::CliRun offline =
        RunCli({"segment", input, "-o", input + ".offline.json", tol[0], tol[1]});
    ASSERT_EQ(offline.exit_code, 0) << name << ": " << offline.err;
    const testing_cli::CliRun remote = RunCli({"segment", input, "-o", input + ".server.json",
                                               tol[0], tol[1], "--server", server.address()});
    ASSERT_EQ(remote.exit_code, 0) << name << ": " << remote.err;
    const std::string a = ReadText(input + ".offline.json");
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(ReadText(input + ".server.json"), a) << name;
  }
}

// The colours of a binary PLY written by meshseg: `count` elements of
// `stride` bytes, starting `skip` bytes after the header (past the vertices
// when they are faces), the last 3 bytes of each the colour.
std::vector<std::array<uint8_t, 3>> PlyColors(const std::string& bytes, size_t skip,
                                              int64_t count, size_t stride) {
  const std::string end = "end_header\n";
  const size_t start = bytes.find(end) + end.size() + skip;
  EXPECT_EQ(bytes.size(), start + count * stride) << "nothing after the colored elements";
  std::vector<std::array<uint8_t, 3>> colors(count);
  for (int64_t i = 0; i < count && start + (i + 1) * stride <= bytes.size(); ++i) {
    for (int c = 0; c < 3; ++c) colors[i][c] = bytes[start + (i + 1) * stride - 3 + c];
  }
  return colors;
}

// Labels and colours correspond one to one: equal labels, equal colours;
// different labels, different colours; -1 grey.
void ExpectColorsFollowLabels(const std::vector<int>& labels,
                              const std::vector<std::array<uint8_t, 3>>& colors) {
  ASSERT_EQ(labels.size(), colors.size());
  std::map<int, std::array<uint8_t, 3>> color_of;
  std::set<std::array<uint8_t, 3>> distinct;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] < 0) {
      EXPECT_EQ(colors[i], (std::array<uint8_t, 3>{128, 128, 128})) << i;
      continue;
    }
    const auto [it, added] = color_of.emplace(labels[i], colors[i]);
    if (added) distinct.insert(colors[i]);
    EXPECT_EQ(it->second, colors[i]) << "element " << i << ", label " << labels[i];
  }
  EXPECT_EQ(distinct.size(), color_of.size()) << "one colour per label";
}

// --colored-ply colours a mesh by face; a point cloud (whose mesh is
// reconstructed and not in the result) by point, the outliers grey.
TEST(MeshsegSegment, ColoredPlyColoursTheFacesOfAMeshAndThePointsOfACloud) {
  const std::string dir = FreshDir("files");
  const testing_files::TestMesh box = testing_files::SplitBox(4, {2.0, 1.0, 0.5});
  testing_files::WriteOff(box, dir + "/box.off");
  testing_files::TestMesh cloud = testing_files::SplitBox(16, {2.0, 1.5, 1.0});
  cloud.v.emplace_back(9.0, 9.0, 9.0);  // far outlier: label -1
  testing_files::WriteXyz(cloud, dir + "/cloud.xyz");

  testing_cli::CliRun r = RunCli({"segment", dir + "/box.off", "-o", dir + "/box.json",
                                  "--colored-ply", dir + "/box.ply"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  v1::SegmentationResult result = ParseResult(ReadText(dir + "/box.json"));
  ASSERT_EQ(result.face_labels_size(), static_cast<int>(box.f.size()));
  const std::string mesh_ply = ReadText(dir + "/box.ply");
  EXPECT_THAT(mesh_ply, HasSubstr("element face " + std::to_string(box.f.size()) + "\n"));
  // Vertices: 3 doubles; faces: 1 count byte, 3 int32 indices, 3 colour bytes.
  ExpectColorsFollowLabels(
      {result.face_labels().begin(), result.face_labels().end()},
      PlyColors(mesh_ply, box.v.size() * 24, static_cast<int64_t>(box.f.size()), 16));

  r = RunCli({"segment", dir + "/cloud.xyz", "-o", dir + "/cloud.json", "--colored-ply",
              dir + "/cloud.ply"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  result = ParseResult(ReadText(dir + "/cloud.json"));
  ASSERT_EQ(result.point_labels_size(), static_cast<int>(cloud.v.size()));
  EXPECT_EQ(result.point_labels(cloud.v.size() - 1), -1) << "the outlier";
  // The far point is the one the outlier test discards; the report says how
  // many points were labelled and discarded, counted from the JSON.
  EXPECT_EQ(result.point_outlier_count(), 1);
  const int64_t labelled = std::count_if(result.point_labels().begin(),
                                         result.point_labels().end(), [](int l) { return l >= 0; });
  EXPECT_EQ(labelled, static_cast<int64_t>(cloud.v.size()) - 1)
      << "every box face has a region, so every other point is labelled";
  EXPECT_THAT(r.out, HasSubstr(absl::StrCat(cloud.v.size(), " points: ", labelled,
                                            " labelled with a region, 1 discarded as outliers\n")));
  const std::string cloud_ply = ReadText(dir + "/cloud.ply");
  EXPECT_THAT(cloud_ply, HasSubstr("element vertex " + std::to_string(cloud.v.size()) + "\n"));
  EXPECT_THAT(cloud_ply, Not(HasSubstr("element face")));
  // Per point: 3 doubles, 3 colour bytes.
  ExpectColorsFollowLabels({result.point_labels().begin(), result.point_labels().end()},
                           PlyColors(cloud_ply, 0, static_cast<int64_t>(cloud.v.size()), 27));
}

TEST(MeshsegSegment, UnreachableServerExitsOneWithOneLine) {
  const std::string dir = FreshDir("files");
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), dir + "/box.off");
  // Port 1 on loopback: nothing listens there.
  const testing_cli::CliRun r =
      RunCli({"segment", dir + "/box.off", "-o", dir + "/r.json", "--server", "127.0.0.1:1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
}

// --request-id makes a retried `segment --server` one job: the same id
// again creates no second job and gives the same result; another id does.
TEST(MeshsegSegment, RequestIdMakesARetryTheSameJob) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  const std::string input = dir + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), input);
  const auto segment = [&](const std::string& id, const std::string& out) {
    return RunCli({"segment", input, "-o", out, "--server", server.address(), "--request-id", id});
  };
  testing_cli::CliRun r = segment("order-17/part-3", dir + "/first.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = segment("order-17/part-3", dir + "/retry.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ReadText(dir + "/retry.json"), ReadText(dir + "/first.json"));
  absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  ASSERT_EQ(jobs->size(), 1u);
  EXPECT_EQ(jobs->front().request_id(), "order-17/part-3");

  r = segment("order-17/part-4", dir + "/other.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  EXPECT_EQ(jobs->size(), 2u);

  // A bad id is the server's INVALID_ARGUMENT, in one line; offline it
  // means nothing and is refused before any work.
  r = segment("two words", dir + "/bad.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("request_id"));
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  r = RunCli({"segment", input, "-o", dir + "/offline.json", "--request-id", "x"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--request-id needs --server"));
}

// --include-mesh and --length-unit: the same bytes offline and from the
// server, with the mesh the curve ids index and the unit echoed.
TEST(MeshsegSegment, IncludeMeshAndLengthUnitGiveTheSameJsonOnBothPaths) {
  TestServer server;
  const std::string dir = FreshDir("files");
  const std::string input = dir + "/box.stl";
  const testing_files::TestMesh box = testing_files::SplitBox(3, {2.0, 1.0, 0.5});
  testing_files::WriteStlBinary(box, input);
  const std::vector<std::string> flags = {"--include-mesh", "--length-unit", "CM"};
  std::vector<std::string> offline = {"segment", input, "-o", dir + "/offline.json"};
  offline.insert(offline.end(), flags.begin(), flags.end());
  testing_cli::CliRun r = RunCli(offline);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> remote = {"segment", input, "-o", dir + "/server.json", "--server",
                                     server.address()};
  remote.insert(remote.end(), flags.begin(), flags.end());
  r = RunCli(remote);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = ReadText(dir + "/offline.json");
  EXPECT_EQ(ReadText(dir + "/server.json"), json);
  const v1::SegmentationResult result = ParseResult(json);
  EXPECT_EQ(result.length_unit(), "cm");
  EXPECT_EQ(result.mesh_geometry().vertices_size(), static_cast<int>(3 * box.v.size()));
  EXPECT_EQ(result.mesh_geometry().faces_size(), static_cast<int>(3 * box.f.size()));
  for (const v1::BoundaryCurve& c : result.curves()) {
    for (int v : c.vertices()) EXPECT_LT(v, static_cast<int>(box.v.size()));
  }

  // An unknown unit, or a STEP unit other than the input's, exits 1 before
  // any work, naming the value.
  r = RunCli({"segment", input, "-o", dir + "/x.json", "--length-unit", "furlong"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("length_unit \"furlong\" is not one of mm, cm"));
  r = RunCli({"segment", input, "-o", dir + "/x.json", "--length-unit", "mm", "--step",
              dir + "/x.step", "--unit", "in"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("step_unit \"in\" is not length_unit \"mm\""));
}

}  // namespace
}  // namespace meshseg
