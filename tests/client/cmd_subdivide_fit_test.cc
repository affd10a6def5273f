// meshseg subdivide-fit IN -o CONTROL.obj [--faces N | --tolerance E] [--limit OUT.ply]:
// the control mesh of a box keeps its twelve edges as creases and its eight
// corners, the limit mesh is written, and bad input gets one clear line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/client/run_cli.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_cli::RunCli;
using testing_server::FreshDir;

TEST(MeshsegSubdivideFit, WritesTaggedControlMeshAndLimitSurface) {
  const std::string dir = FreshDir("subdivide_fit");
  testing_files::WriteObj(testing_files::SplitBox(8, {2.0, 1.0, 1.0}),
                          dir + "/box.obj");  // 768 faces
  const testing_cli::CliRun run =
      RunCli({"subdivide-fit", dir + "/box.obj", "-o", dir + "/control.obj", "--faces", "80",
              "--limit", dir + "/limit.ply"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("control mesh of"));
  std::ifstream in(dir + "/control.obj");
  int faces = 0, creases = 0, corners = 0;
  for (std::string line; std::getline(in, line);) {
    faces += line.rfind("f ", 0) == 0;
    creases += line.rfind("t crease 2/1/0 ", 0) == 0;
    corners += line.rfind("t corner 1/1/0 ", 0) == 0;
  }
  EXPECT_LE(faces, 80);
  EXPECT_GE(creases, 12);  // every box edge, split into one or more crease edges
  EXPECT_EQ(corners, 8);
  EXPECT_TRUE(std::ifstream(dir + "/limit.ply").good());
}

TEST(MeshsegSubdivideFit, BadInputGetsOneClearLine) {
  const std::string dir = FreshDir("subdivide_fit_bad");
  testing_files::WriteObj(testing_files::SplitBox(2, {1.0, 1.0, 1.0}), dir + "/box.obj");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"subdivide-fit", dir + "/missing.obj", "-o", dir + "/c.obj"}, "missing.obj"},
      {{"subdivide-fit", dir + "/box.obj", "-o", dir + "/c.ply"}, "written as OBJ"},
      {{"subdivide-fit", dir + "/box.obj", "-o", dir + "/c.obj", "--faces", "2"},
       "--faces 2 must be a whole number of at least 4"},
      {{"subdivide-fit", dir + "/box.obj", "-o", dir + "/c.obj", "--faces", "10", "--tolerance",
        "0.1"},
       "not both"},
      {{"subdivide-fit", dir + "/box.obj", "-o", dir + "/c.obj", "--faces", "100"},
       "target_faces 100 exceeds the 48 faces"},
  };
  for (const Case& c : cases) {
    const testing_cli::CliRun run = RunCli(c.args);
    EXPECT_EQ(run.exit_code, 1) << c.message;
    EXPECT_THAT(run.err, HasSubstr(c.message));
    EXPECT_EQ(testing_cli::Lines(run.err).size(), 1u) << run.err;
  }
}

}  // namespace
}  // namespace meshseg
