// CT volumes through the `meshseg` binary: `generate PART --volume` writes a
// volume (and its extracted surface and ground truth), `info VOL` shows its
// header, `segment VOL` segments it (NRRD and a headerless .raw with its
// layout flags), scored against the generator's ground truth; bad volume
// input is one line on stderr and exit code 1. small_block at its default
// h = 0.4 keeps every volume near 100 000 voxels (about a second a run).
#include <gmock/gmock.h>
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "meshseg/v1/segmentation.pb.h"
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
using testing_files::ReadText;
using testing_server::FreshDir;

constexpr char kVoxelSize[] = "0.4";  // small_block's default h
constexpr int kBlockSurfaces = 8;     // small_block: 6 planes, the bore, the round

v1::SegmentationResult ParseResult(const std::string& json) {
  v1::SegmentationResult result;
  const auto status = google::protobuf::util::JsonStringToMessage(json, &result);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return result;
}

struct GeneratedVolume {
  std::string volume, surface, truth;
};

GeneratedVolume Generate(const std::string& dir, bool binary) {
  GeneratedVolume g{dir + (binary ? "/block_binary.nrrd" : "/block_grey.nrrd"),
                    dir + "/surface.ply", dir + "/truth.json"};
  std::vector<std::string> args = {"generate",       "small_block", "--voxel-size", kVoxelSize,
                                   "--volume",       g.volume,      "-o",           g.surface,
                                   "--ground-truth", g.truth};
  if (binary) args.push_back("--binary");
  const testing_cli::CliRun r = RunCli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("wrote " + g.volume + ": part small_block"));
  EXPECT_THAT(r.out, HasSubstr(binary ? "binary voxels, h=0.4" : "grey voxels, h=0.4"));
  return g;
}

// Share of the faces away from true boundaries (face_near_boundary 0) whose
// region's majority there is their own true surface (face_primitive), from
// the result's labels.
double FaceAccuracy(const v1::SegmentationResult& result, const std::string& truth_json) {
  google::protobuf::Struct truth;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(truth_json, &truth).ok());
  const auto& primitive = truth.fields().at("face_primitive").list_value().values();
  const auto& near = truth.fields().at("face_near_boundary").list_value().values();
  EXPECT_EQ(primitive.size(), static_cast<size_t>(result.face_labels_size()));
  std::map<int, std::map<int, int>> votes;  // region -> primitive -> faces
  int counted = 0;
  for (int f = 0; f < result.face_labels_size() && f < primitive.size(); ++f) {
    if (near[f].number_value() != 0) continue;
    ++counted;
    ++votes[result.face_labels(f)][static_cast<int>(primitive[f].number_value())];
  }
  int right = 0;
  for (const auto& [region, counts] : votes) {
    if (region < 0) continue;
    int best = 0;
    for (const auto& [p, n] : counts) best = std::max(best, n);
    right += best;
  }
  return static_cast<double>(right) / std::max(1, counted);
}

TEST(MeshsegVolume, GenerateWritesAVolumeThatInfoDescribes) {
  const std::string dir = FreshDir("files");
  const GeneratedVolume g = Generate(dir, /*binary=*/false);
  const testing_cli::CliRun r = RunCli({"info", g.volume, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(Lines(r.out), SizeIs(1)) << "one JSON object on one line";
  const auto fields = ParseJsonObject(r.out).fields();
  EXPECT_EQ(fields.at("format").string_value(), "nrrd");
  EXPECT_EQ(fields.at("voxel_type").string_value(), "uint16");
  EXPECT_EQ(fields.at("encoding").string_value(), "gzip");
  const auto& dims = fields.at("dims").list_value().values();
  ASSERT_EQ(dims.size(), 3);
  // The 20 x 14 x 8 block (tilted) fits in its grid at h = 0.4 with a margin.
  double product = 1.0;
  for (const auto& d : dims) {
    EXPECT_GE(d.number_value(), 8 / 0.4);
    EXPECT_LE(d.number_value(), 100);
    product *= d.number_value();
  }
  EXPECT_EQ(fields.at("voxel_count").number_value(), product);
  for (const auto& s : fields.at("spacing").list_value().values()) {
    EXPECT_DOUBLE_EQ(s.number_value(), 0.4);
  }
  // The text form names the same sizes.
  const testing_cli::CliRun text = RunCli({"info", g.volume});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("nrrd volume"));
  EXPECT_THAT(text.out, HasSubstr(absl::StrCat(static_cast<int>(dims[0].number_value()), " x ",
                                               static_cast<int>(dims[1].number_value()), " x ",
                                               static_cast<int>(dims[2].number_value()))));
}

TEST(MeshsegVolume, SegmentOfBinaryAndGreyVolumesMatchesTheTruth) {
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "grey");
    const std::string dir = FreshDir(binary ? "binary" : "grey");
    const GeneratedVolume g = Generate(dir, binary);
    const std::string out = dir + "/result.json";
    const testing_cli::CliRun r =
        RunCli({"segment", g.volume, "-o", out, "--colored-ply", dir + "/colored.ply"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("wrote " + out));
    const v1::SegmentationResult result = ParseResult(ReadText(out));
    EXPECT_EQ(result.binary_occupancy(), binary);
    ASSERT_TRUE(result.has_volume());
    EXPECT_EQ(result.volume().format(), "nrrd");
    EXPECT_EQ(result.volume().voxel_type(), binary ? "uint8" : "uint16");
    EXPECT_EQ(result.regions_size(), kBlockSurfaces);
    // One label per face of the surface generate extracted (-o).
    const std::string surface = ReadText(g.surface);
    EXPECT_THAT(surface, HasSubstr(absl::StrCat("element face ", result.face_labels_size())));
    EXPECT_GE(FaceAccuracy(result, ReadText(g.truth)), 0.98);
    EXPECT_THAT(ReadText(dir + "/colored.ply"),
                HasSubstr(absl::StrCat("element face ", result.face_labels_size())));
  }
}

TEST(MeshsegVolume, SegmentOfARawVolumeTakesItsLayoutFromFlags) {
  const std::string dir = FreshDir("files");
  const GeneratedVolume g = Generate(dir, /*binary=*/false);
  const auto fields = ParseJsonObject(RunCli({"info", g.volume, "--json"}).out).fields();
  const auto& dims = fields.at("dims").list_value().values();
  const auto& origin = fields.at("origin").list_value().values();
  const std::string nrrd_json = dir + "/nrrd.json";
  ASSERT_EQ(RunCli({"segment", g.volume, "-o", nrrd_json}).exit_code, 0);

  // The same samples without a header: the generator writes raw (not gzip)
  // encoding when the name does not end in .nrrd; the samples follow the
  // header's blank line.
  const std::string plain = dir + "/block_plain.vol";
  ASSERT_EQ(
      RunCli({"generate", "small_block", "--voxel-size", kVoxelSize, "--volume", plain}).exit_code,
      0);
  const std::string bytes = ReadText(plain);
  const std::size_t data = bytes.find("\n\n");
  ASSERT_NE(data, std::string::npos);
  const std::string raw = dir + "/block.raw";
  testing_files::WriteText(raw, bytes.substr(data + 2));

  const auto n = [](const google::protobuf::Value& v) {
    return absl::StrCat(static_cast<int64_t>(v.number_value()));
  };
  const auto x = [](const google::protobuf::Value& v) {
    return absl::StrFormat("%.17g", v.number_value());
  };
  const std::string raw_json = dir + "/raw.json";
  const testing_cli::CliRun r = RunCli(
      {"segment", raw, "-o", raw_json, "--dims",
       absl::StrCat(n(dims[0]), ",", n(dims[1]), ",", n(dims[2])), "--spacing",
       absl::StrCat(kVoxelSize, ",", kVoxelSize, ",", kVoxelSize), "--origin",
       absl::StrCat(x(origin[0]), ",", x(origin[1]), ",", x(origin[2])), "--type", "uint16"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const v1::SegmentationResult from_raw = ParseResult(ReadText(raw_json));
  const v1::SegmentationResult from_nrrd = ParseResult(ReadText(nrrd_json));
  EXPECT_EQ(from_raw.volume().format(), "raw");
  EXPECT_EQ(from_raw.regions_size(), from_nrrd.regions_size());
  ASSERT_EQ(from_raw.face_labels_size(), from_nrrd.face_labels_size());
  EXPECT_TRUE(std::equal(from_raw.face_labels().begin(), from_raw.face_labels().end(),
                         from_nrrd.face_labels().begin()));

  // Without the layout: one line naming the file and what is missing.
  const testing_cli::CliRun bare = RunCli({"segment", raw, "-o", dir + "/bare.json"});
  EXPECT_EQ(bare.exit_code, 1);
  EXPECT_THAT(Lines(bare.err), SizeIs(1)) << bare.err;
  EXPECT_THAT(bare.err, HasSubstr("block.raw"));
  // A layout whose size disagrees with the file's.
  const testing_cli::CliRun wrong =
      RunCli({"segment", raw, "-o", dir + "/wrong.json", "--dims", "10,10,10", "--type", "uint16"});
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_THAT(wrong.err, HasSubstr("block.raw"));
}

}  // namespace
}  // namespace meshseg
