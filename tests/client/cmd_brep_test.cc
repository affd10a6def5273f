// meshseg segment --step and meshseg brep: the STEP file of a segmented part
// (its header, one named ADVANCED_FACE per region, a closed solid), the same
// file from a saved result, and errors that are one line naming the problem.
#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "meshseg/v1/segmentation.pb.h"
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
using testing_server::FreshDir;

// The names of the ADVANCED_FACE entities of a STEP file.
std::multiset<std::string> FaceNames(const std::string& step) {
  std::multiset<std::string> out;
  const std::regex face("ADVANCED_FACE\\('([^']*)'");
  for (auto it = std::sregex_iterator(step.begin(), step.end(), face); it != std::sregex_iterator();
       ++it) {
    out.insert((*it)[1]);
  }
  return out;
}

// A generated part segmented with --step, shared by the tests below.
struct Segmented {
  std::string dir, mesh, json, step;
  v1::SegmentationResult result;
};

const Segmented& SmallBlock() {
  static const Segmented* s = [] {
    auto* out = new Segmented;
    out->dir = FreshDir("brep");
    out->mesh = out->dir + "/small_block.ply";
    out->json = out->dir + "/small_block.json";
    out->step = out->dir + "/small_block.step";
    const testing_cli::CliRun g =
        RunCli({"generate", "small_block", "-o", out->mesh, "--noise", "0.05"});
    EXPECT_EQ(g.exit_code, 0) << g.err;
    const testing_cli::CliRun r =
        RunCli({"segment", out->mesh, "-o", out->json, "--step", out->step});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("step: "));
    EXPECT_THAT(r.out, HasSubstr("closed solid, valid"));
    EXPECT_THAT(r.out, HasSubstr("wrote " + out->step));
    const auto status =
        google::protobuf::util::JsonStringToMessage(ReadText(out->json), &out->result);
    EXPECT_TRUE(status.ok()) << status.ToString();
    return out;
  }();
  return *s;
}

TEST(MeshsegBrep, SegmentWritesAStepSolidWithANamedFacePerRegion) {
  const Segmented& s = SmallBlock();
  const std::string step = ReadText(s.step);
  EXPECT_THAT(step, HasSubstr("ISO-10303-21;"));
  EXPECT_THAT(step, HasSubstr("AUTOMOTIVE_DESIGN"));  // AP214
  EXPECT_THAT(step, HasSubstr("MANIFOLD_SOLID_BREP"));
  EXPECT_THAT(step, HasSubstr("SI_UNIT(.MILLI.,.METRE.)"));
  const std::multiset<std::string> names = FaceNames(step);
  ASSERT_EQ(static_cast<int>(names.size()), s.result.brep().face_count());
  for (const v1::Region& r : s.result.regions()) {
    EXPECT_GE(names.count("region " + std::to_string(r.id()) + " " +
                          (r.has_plane() ? "plane" : "cylinder")),
              1u)
        << "region " << r.id();
  }
  // The report in the result JSON.
  const v1::BrepReport& b = s.result.brep();
  EXPECT_TRUE(b.solid());
  EXPECT_TRUE(b.valid());
  EXPECT_EQ(b.face_count(), b.patch_count());
  EXPECT_EQ(b.region_count(), s.result.regions_size());
  EXPECT_EQ(b.length_unit(), "mm");
  EXPECT_EQ(b.step_size(), static_cast<int64_t>(std::filesystem::file_size(s.step)));
  EXPECT_EQ(b.error(), "");
}

TEST(MeshsegBrep, BrepFromTheSavedResultWritesTheSameFaces) {
  const Segmented& s = SmallBlock();
  const std::string out = s.dir + "/again.step";
  const testing_cli::CliRun r = RunCli({"brep", s.json, s.mesh, "-o", out, "--unit", "cm"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("closed solid, valid"));
  const std::string step = ReadText(out);
  EXPECT_EQ(FaceNames(step), FaceNames(ReadText(s.step)));
  EXPECT_THAT(step, HasSubstr("SI_UNIT(.CENTI.,.METRE.)"));
}

TEST(MeshsegBrep, SegmentOnTheServerFetchesTheSameStepFaces) {
  const Segmented& s = SmallBlock();
  testing_server::TestServer server;
  const std::string json = s.dir + "/server.json", step = s.dir + "/server.step";
  const testing_cli::CliRun r =
      RunCli({"segment", s.mesh, "-o", json, "--step", step, "--server", server.address()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("closed solid, valid"));
  EXPECT_THAT(r.out, HasSubstr("wrote " + step));
  // The server runs the same pipeline: the same faces, by name.
  EXPECT_EQ(FaceNames(ReadText(step)), FaceNames(ReadText(s.step)));
  v1::SegmentationResult result;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(ReadText(json), &result).ok());
  EXPECT_EQ(result.brep().step_size(), static_cast<int64_t>(std::filesystem::file_size(step)));
}

TEST(MeshsegBrep, ErrorsAreOneLineNamingTheProblem) {
  const Segmented& s = SmallBlock();
  const std::string dir = FreshDir("brep_errors");
  const std::string box = dir + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(3, {2.0, 1.0, 0.5}), box);
  const std::string bad_json = dir + "/bad.json";
  testing_files::WriteText(bad_json, "{\"regions\": [");
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  for (const Case& c : std::vector<Case>{
           {{"brep", s.json, s.mesh}, "-o OUT.step"},
           {{"brep", s.json, box, "-o", dir + "/x.step"}, "box.off"},
           {{"brep", bad_json, s.mesh, "-o", dir + "/x.step"}, "bad.json"},
           {{"brep", dir + "/missing.json", s.mesh, "-o", dir + "/x.step"}, "missing.json"},
           {{"brep", s.json, s.mesh, "-o", dir + "/x.step", "--unit", "cubit"}, "cubit"},
           {{"segment", box, "-o", dir + "/r.json", "--unit", "m"}, "--step"},
       }) {
    const testing_cli::CliRun r = RunCli(c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args[0] << " " << c.says;
    EXPECT_THAT(Lines(r.err), SizeIs(1)) << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.says));
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.step"));
}

}  // namespace
}  // namespace meshseg
