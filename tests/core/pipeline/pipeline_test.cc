// RunPipeline's length unit and returned mesh: the unit is checked, echoed
// lowercase and must be the STEP file's; the returned mesh is the input's
// also when the segmentation ran on a remesh of it.
#include "meshseg/pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scratch_dir.h"
#include "server/test_files.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

std::string WriteBox() {
  const std::string path = testing_files::ScratchPath("box.off");
  testing_files::WriteOff(testing_files::SplitBox(2, {2.0, 1.0, 1.0}), path);
  return path;
}

TEST(RunPipeline, EchoesTheLengthUnitLowercaseAndRefusesAnUnknownOne) {
  const std::string path = WriteBox();
  PipelineParams params;
  absl::StatusOr<PipelineResult> r = RunPipeline(path, params);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(r->length_unit, "");
  params.length_unit = "FT";
  r = RunPipeline(path, params);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(r->length_unit, "ft");
  params.length_unit = "cubit";
  r = RunPipeline(path, params);
  EXPECT_TRUE(absl::IsInvalidArgument(r.status())) << r.status();
  EXPECT_THAT(r.status().message(), HasSubstr("length_unit \"cubit\" is not one of mm, cm"));
}

TEST(RunPipeline, RefusesAStepUnitOtherThanTheInputsBeforeReading) {
  PipelineParams params;
  params.length_unit = "m";
  params.step_path = testing_files::ScratchPath("box.step");
  params.brep.length_unit = "mm";
  const absl::StatusOr<PipelineResult> r = RunPipeline("/nonexistent.off", params);
  EXPECT_TRUE(absl::IsInvalidArgument(r.status())) << r.status();
  EXPECT_THAT(r.status().message(), HasSubstr("\"mm\" is not the input's length_unit \"m\""));
}

// Segmented on a remesh (about 20 times as many faces): the returned mesh
// and the curve ids are still those of the 48-triangle input.
TEST(RunPipeline, IncludeMeshReturnsTheInputMeshAlsoWhenSegmentedOnARemesh) {
  PipelineParams params;
  params.include_mesh = true;
  params.remesh.mode = RemeshMode::kAlways;
  params.remesh.target_edge_length = 0.2;
  const absl::StatusOr<PipelineResult> r = RunPipeline(WriteBox(), params);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_GT(r->remesh_face_count, 48);
  ASSERT_TRUE(r->mesh_geometry.has_value());
  const MeshGeometry& g = *r->mesh_geometry;
  EXPECT_EQ(g.vertices.size(), 26u);
  EXPECT_EQ(g.faces.size(), 48u);
  EXPECT_EQ(g.input_face.size(), 48u);
  ASSERT_FALSE(r->topology.curves.empty());
  for (const BoundaryCurve& c : r->topology.curves) {
    for (int v : c.vertices) EXPECT_LT(v, 26);
  }
  EXPECT_FALSE(RunPipeline(WriteBox())->mesh_geometry.has_value()) << "only when asked";
}

}  // namespace
}  // namespace meshseg
