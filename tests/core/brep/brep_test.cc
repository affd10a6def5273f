// WriteStep on a small generated part with its ground-truth segmentation:
// the STEP file read back is one valid solid with a named face per region,
// in the declared unit; a face that cannot be built is reported and the rest
// written; bad input gets a clear error.
#include "meshseg/brep.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stop_token>
#include <string>

#include "ground_truth_regions.h"
#include "meshseg/generate.h"
#include "meshseg/topology.h"
#include "scratch_dir.h"
#include "step_checks.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

constexpr double kVolumeTolerance = 0.005;  // relative, the 0.5 %

// A 20 x 14 x 8 block with a through bore and a rounded edge, at the
// default resolution with noise 0.05 h, segmented by its ground truth.
struct Case {
  GeneratedPart part;
  testing::TruthSegmentation truth;
  Topology topology;
};

const Case& SmallBlock() {
  static const Case* c = [] {
    auto* out = new Case;
    absl::StatusOr<GeneratedPart> part = GeneratePart("small_block", {.noise = 0.05});
    EXPECT_TRUE(part.ok()) << part.status();
    out->part = *std::move(part);
    out->truth = testing::TruthOf(out->part);
    absl::StatusOr<Topology> topo =
        ExtractTopology(out->part.mesh, out->truth.face_labels, out->truth.regions);
    EXPECT_TRUE(topo.ok()) << topo.status();
    out->topology = *std::move(topo);
    return out;
  }();
  return *c;
}

absl::StatusOr<BrepReport> Write(const Case& c, const std::string& path,
                                 const BrepParams& params = {}) {
  BrepParams p = params;
  if (!p.noise_sigma) p.noise_sigma = c.part.noise;
  return WriteStep(c.part.mesh, c.truth.face_labels, c.truth.regions, c.topology, path, p);
}

TEST(WriteStep, SmallBlockIsOneValidSolidWithANamedFacePerRegion) {
  const Case& c = SmallBlock();
  const std::string path = testing_files::ScratchPath("small_block.step");
  absl::StatusOr<BrepReport> report = Write(c, path);
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_TRUE(report->solid);
  EXPECT_TRUE(report->closed);
  EXPECT_TRUE(report->valid);
  EXPECT_TRUE(report->failures.empty()) << report->failures[0].reason;
  EXPECT_EQ(report->region_count, static_cast<int>(c.truth.regions.size()));
  EXPECT_EQ(report->face_count, report->patch_count);
  EXPECT_EQ(report->exact_edge_count + report->fitted_edge_count, report->edge_count);
  EXPECT_GT(report->step_size, 0);
  EXPECT_EQ(report->step_size, static_cast<int64_t>(std::filesystem::file_size(path)));

  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  ASSERT_TRUE(model.ok()) << model.status();
  const testing::ShapeFacts facts = testing::FactsOf(model->shape);
  EXPECT_TRUE(facts.valid);
  EXPECT_EQ(facts.solids, 1);
  EXPECT_EQ(facts.free_edges, 0);
  EXPECT_EQ(facts.faces, report->face_count);
  const double mesh_volume = testing::EnclosedVolume(c.part.mesh.tri);
  EXPECT_NEAR(facts.volume, mesh_volume, kVolumeTolerance * mesh_volume);
  EXPECT_NEAR(facts.volume, report->volume, 1e-6 * mesh_volume);
  // Every region is there by name, with its surface type.
  std::set<std::string> names(model->face_names.begin(), model->face_names.end());
  for (const Region& r : c.truth.regions) {
    const std::string name = "region " + std::to_string(r.id) + " " + SurfaceTypeName(r.type);
    EXPECT_TRUE(names.count(name)) << name;
  }
  EXPECT_EQ(model->length_unit, "millimetre");
}

TEST(WriteStep, CoordinatesAreWrittenInTheDeclaredUnit) {
  const Case& c = SmallBlock();
  const std::string path = testing_files::ScratchPath("small_block_m.step");
  absl::StatusOr<BrepReport> report = Write(c, path, {.length_unit = "m"});
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_EQ(report->length_unit, "m");
  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  ASSERT_TRUE(model.ok()) << model.status();
  EXPECT_EQ(model->length_unit, "metre");
  // The reader converts to millimetres: the values were metres, unscaled.
  const double mesh_volume = testing::EnclosedVolume(c.part.mesh.tri);
  EXPECT_NEAR(testing::FactsOf(model->shape).volume, 1e9 * mesh_volume,
              kVolumeTolerance * 1e9 * mesh_volume);
}

TEST(WriteStep, AFaceThatCannotBeBuiltIsReportedAndTheRestWritten) {
  const Case& c = SmallBlock();
  const int bore = testing::PrimitiveId(c.part, "bore");
  ASSERT_GE(bore, 0);
  std::vector<Region> regions = c.truth.regions;
  std::get<Cylinder>(regions[bore].surface).radius = -1.0;
  const std::string path = testing_files::ScratchPath("no_bore.step");
  absl::StatusOr<BrepReport> report = WriteStep(c.part.mesh, c.truth.face_labels, regions,
                                                c.topology, path, {.noise_sigma = c.part.noise});
  ASSERT_TRUE(report.ok()) << report.status();
  ASSERT_EQ(report->failures.size(), 1u);
  EXPECT_EQ(report->failures[0].region, bore);
  EXPECT_THAT(report->failures[0].reason, HasSubstr("cylinder"));
  EXPECT_FALSE(report->solid);
  EXPECT_FALSE(report->closed);
  EXPECT_EQ(report->face_count, report->patch_count - 1);
  absl::StatusOr<testing::StepModel> model = testing::ReadStep(path);
  ASSERT_TRUE(model.ok()) << model.status();
  const testing::ShapeFacts facts = testing::FactsOf(model->shape);
  EXPECT_EQ(facts.solids, 0);
  EXPECT_EQ(facts.faces, report->face_count);
  EXPECT_GT(facts.free_edges, 0) << "the bore's two circles are open";
}

TEST(WriteStep, BadInputNamesTheProblem) {
  const Case& c = SmallBlock();
  const std::string path = testing_files::ScratchPath("never.step");
  const Mesh& mesh = c.part.mesh;
  auto write = [&](std::span<const int> labels, std::span<const Region> regions,
                   const Topology& topo, const BrepParams& params) {
    return WriteStep(mesh, labels, regions, topo, path, params).status();
  };
  absl::Status s = write(c.truth.face_labels, c.truth.regions, c.topology, {.length_unit = "yd"});
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("\"yd\""));
  s = write(c.truth.face_labels, c.truth.regions, c.topology, {.sewing_tolerance = -1.0});
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("sewing_tolerance"));

  const std::vector<int> short_labels(c.truth.face_labels.begin(), c.truth.face_labels.end() - 1);
  s = write(short_labels, c.truth.regions, c.topology, {});
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("face labels"));

  std::vector<int> bad_labels = c.truth.face_labels;
  bad_labels[3] = 99;
  s = write(bad_labels, c.truth.regions, c.topology, {});
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("label 99"));

  Topology broken = c.topology;
  broken.loops[0].curves[0].curve = 1000;
  s = write(c.truth.face_labels, c.truth.regions, broken, {});
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("curve 1000"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WriteStep, NoBuildableFaceIsAFailedPrecondition) {
  const Case& c = SmallBlock();
  std::vector<Region> regions = c.truth.regions;
  for (Region& r : regions) {
    r.surface = Sphere{Eigen::Vector3d::Zero(), -1.0};
    r.type = SurfaceType::kSphere;
  }
  const absl::Status s = WriteStep(c.part.mesh, c.truth.face_labels, regions, c.topology,
                                   testing_files::ScratchPath("none.step"))
                             .status();
  EXPECT_TRUE(absl::IsFailedPrecondition(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("no face"));
}

TEST(WriteStep, UnwritablePathIsInternalNamingIt) {
  const Case& c = SmallBlock();
  const std::string path = testing_files::ScratchPath("missing_dir/out.step");
  const absl::Status s = Write(c, path).status();
  EXPECT_TRUE(absl::IsInternal(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr(path));
}

TEST(WriteStep, StopRequestedIsCancelled) {
  const Case& c = SmallBlock();
  std::stop_source stop;
  stop.request_stop();
  RunContext ctx;
  ctx.stop = stop.get_token();
  const absl::Status s = WriteStep(c.part.mesh, c.truth.face_labels, c.truth.regions, c.topology,
                                   testing_files::ScratchPath("stopped.step"), {}, ctx)
                             .status();
  EXPECT_TRUE(absl::IsCancelled(s)) << s;
}

}  // namespace
}  // namespace meshseg
