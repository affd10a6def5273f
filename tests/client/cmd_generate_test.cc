// `meshseg generate CAD_PART --cad`: writes the exact tessellation as STL or
// OBJ and its ground truth, in the unit asked for; bad flags are one line on
// stderr and exit code 1.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"

#include "meshseg/mesh.h"
#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_cli::RunCli;
using testing_files::ReadText;
using testing_server::FreshDir;

TEST(CliGenerateCad, WritesTheTessellationAndItsGroundTruthInTheUnitAskedFor) {
  const std::string dir = FreshDir("generate_cad");
  const std::string mm = dir + "/tube_mm.obj", um = dir + "/tube_um.stl", gt = dir + "/gt.json";
  testing_cli::CliRun r = RunCli({"generate", "cad_tube", "--cad", "-o", mm});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + mm + ": CAD part cad_tube"));
  EXPECT_THAT(r.out, HasSubstr("4 B-rep faces, coarse deflection, mm"));
  r = RunCli({"generate", "cad_tube", "--cad", "-o", um, "--unit", "um", "--ground-truth", gt});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const absl::StatusOr<Mesh> a = ReadMesh(mm);
  const absl::StatusOr<Mesh> b = ReadMesh(um);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->tri.n_faces(), b->tri.n_faces());
  ASSERT_EQ(a->tri.n_vertices(), b->tri.n_vertices());  // the STL welds back closed
  const MeshStats sa = MeshStatistics(*a), sb = MeshStatistics(*b);
  EXPECT_EQ(sb.boundary_edge_count, 0);
  const double da = (sa.bbox_max - sa.bbox_min).norm(), db = (sb.bbox_max - sb.bbox_min).norm();
  EXPECT_NEAR(db, 1000.0 * da, 1e-6 * db);
  const std::string json = ReadText(gt);
  EXPECT_THAT(json, HasSubstr("\"name\": \"cad_tube\""));
  EXPECT_THAT(json, HasSubstr(absl::StrCat("\"face_count\": ", b->tri.n_faces())));
  EXPECT_THAT(json, HasSubstr("\"radius\": 9400"));  // r 9.4 mm in micrometres
  // Fine has more facets.
  r = RunCli({"generate", "cad_tube", "--cad", "-o", mm, "--deflection", "fine"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const absl::StatusOr<Mesh> fine = ReadMesh(mm);
  ASSERT_TRUE(fine.ok());
  EXPECT_GT(fine->tri.n_faces(), a->tri.n_faces());
}

TEST(CliGenerateCad, BadFlagsAreNamed) {
  const std::string out = FreshDir("generate_cad_bad") + "/x.stl";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"generate", "cad_tube", "--cad", "-o", out, "--deflection", "medium"},
       "--deflection \"medium\": expected coarse or fine"},
      {{"generate", "cad_tube", "--cad", "-o", out, "--unit", "inch"}, "unknown unit \"inch\""},
      {{"generate", "cad_tube", "--cad", "-o", out, "--voxel-size", "0.5"},
       "--voxel-size does not apply to --cad parts"},
      {{"generate", "cad_teapot", "--cad", "-o", out}, "unknown CAD part \"cad_teapot\""},
      {{"generate", "small_block", "-o", out, "--unit", "m"}, "--unit goes with --cad"},
      {{"generate", "cad_tube", "--cad", "-o", FreshDir("generate_cad_bad") + "/x.nrrd"},
       "unsupported extension \"nrrd\""},
  };
  for (const auto& [args, message] : cases) {
    const testing_cli::CliRun r = RunCli(args);
    EXPECT_EQ(r.exit_code, 1) << message;
    EXPECT_THAT(r.err, HasSubstr(message));
  }
}

}  // namespace
}  // namespace meshseg
