// meshseg info FILE --json: the fields DESIGN.md promises, against the
// known counts of a split box, and the point-cloud fields.
#include <array>
#include <set>
#include <utility>

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
using testing_cli::ParseJsonObject;
using testing_cli::RunCli;
using testing_server::FreshDir;

// Mean length over the unique edges of `m`.
double MeanEdgeLength(const testing_files::TestMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& f : m.f) {
    for (int k = 0; k < 3; ++k) {
      edges.insert(std::minmax(f[k], f[(k + 1) % 3]));
    }
  }
  double sum = 0.0;
  for (const auto& [a, b] : edges) sum += (m.v[a] - m.v[b]).norm();
  return sum / static_cast<double>(edges.size());
}

TEST(MeshsegInfo, JsonHasTheDesignFieldsOfAMesh) {
  const testing_files::TestMesh box = testing_files::SplitBox(3, {2.0, 1.0, 0.5});
  const std::string path = FreshDir("files") + "/box.obj";
  testing_files::WriteObj(box, path);
  const testing_cli::CliRun r = RunCli({"info", path, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(Lines(r.out), SizeIs(1)) << "one JSON object on one line";
  const auto fields = ParseJsonObject(r.out).fields();
  ASSERT_TRUE(fields.contains("vertex_count"));
  EXPECT_EQ(fields.at("vertex_count").number_value(), 6 * 9 + 2);
  EXPECT_EQ(fields.at("face_count").number_value(), 12 * 9);
  EXPECT_NEAR(fields.at("mean_edge_length").number_value(), MeanEdgeLength(box), 1e-12);
  EXPECT_EQ(fields.at("boundary_edge_count").number_value(), 0);
  EXPECT_EQ(fields.at("component_count").number_value(), 1);
}

TEST(MeshsegInfo, FaceCountIsAsReadFromTheFile) {
  // Two triangles, the second degenerate (repeated index): the file holds 2.
  const std::string path = FreshDir("files") + "/degenerate.off";
  testing_files::WriteText(path, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 1 3\n");
  const testing_cli::CliRun r = RunCli({"info", path, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto fields = ParseJsonObject(r.out).fields();
  EXPECT_EQ(fields.at("face_count").number_value(), 2);
  EXPECT_EQ(fields.at("boundary_edge_count").number_value(), 3);
}

TEST(MeshsegInfo, JsonOfAPointCloudHasPointCountAndNormals) {
  const testing_files::TestMesh box = testing_files::SplitBox(4, {1, 1, 1});
  const std::string dir = FreshDir("files");
  testing_files::WriteXyz(box, dir + "/box.xyz");
  testing_files::WritePwn(box, dir + "/box.pwn");
  testing_files::WritePlyPointsBinary(box, dir + "/box_points.ply");
  for (const auto& [file, normals] : std::vector<std::pair<std::string, bool>>{
           {"box.xyz", false}, {"box.pwn", true}, {"box_points.ply", true}}) {
    const testing_cli::CliRun r = RunCli({"info", dir + "/" + file, "--json"});
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    const auto fields = ParseJsonObject(r.out).fields();
    ASSERT_TRUE(fields.contains("point_count")) << file << ": " << r.out;
    EXPECT_EQ(fields.at("point_count").number_value(), static_cast<double>(box.v.size())) << file;
    EXPECT_EQ(fields.at("has_normals").bool_value(), normals) << file;
  }
}

TEST(MeshsegInfo, MissingFileExitsOneNamingIt) {
  const testing_cli::CliRun r = RunCli({"info", "/nonexistent/part.stl", "--json"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("part.stl"));
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace meshseg
