// SetTopology (via ToProto): every field of curves, loops, corners, adjacency
// and features reaches the message and the JSON; and a real pipeline run on
// a generated part carries its fillet, extrusion and revolution through.
#include "proto/src/topology_to_proto.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

PipelineResult OneOfEach() {
  PipelineResult r;
  BoundaryCurve c;
  c.id = 0;
  c.vertices = {4, 5, 6, 4};
  c.left_region = 1;
  c.right_region = 2;
  c.closed = true;
  c.normal_angle_deg = 90.0;
  c.sharp = true;
  c.convexity = CurveConvexity::kConcave;
  c.geometry = {.type = CurveGeometryType::kCircle,
                .point = {1, 2, 3},
                .direction = {0, 0, 1},
                .radius = 7.5,
                .analytic = true,
                .max_deviation = 0.25};
  c.length = 47.1;
  r.topology.curves.push_back(c);
  r.topology.loops.push_back(
      Loop{.id = 0, .region = 2, .patch = 1, .kind = LoopKind::kAxial, .curves = {{0, true}}});
  r.topology.corners.push_back(Corner{.id = 0,
                                      .vertex = 9,
                                      .cluster = 0,
                                      .position = {3, 2, 1},
                                      .snapped = true,
                                      .regions = {-1, 1, 2},
                                      .curves = {0, 0}});
  r.topology.adjacency.push_back(Adjacency{.region_a = 1, .region_b = 2, .curves = {0}});
  r.features.push_back(Feature{.id = 0,
                               .type = FeatureType::kFilletTorusCylinderPlane,
                               .regions = {2, 1, 0},
                               .radius = 4.0,
                               .convex = true,
                               .opening_angle_deg = 0.0,
                               .direction = {0, 1, 0},
                               .point = {5, 5, 5}});
  r.point_labels = {0, -1, 2};
  return r;
}

TEST(TopologyToProto, EveryFieldOfEachKindArrives) {
  const v1::SegmentationResult p = ToProto(OneOfEach());
  ASSERT_EQ(p.curves_size(), 1);
  const v1::BoundaryCurve& c = p.curves(0);
  EXPECT_THAT(c.vertices(), ElementsAre(4, 5, 6, 4));
  EXPECT_EQ(c.left_region(), 1);
  EXPECT_EQ(c.right_region(), 2);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.start_corner(), -1);
  EXPECT_DOUBLE_EQ(c.normal_angle_deg(), 90.0);
  EXPECT_TRUE(c.sharp());
  EXPECT_EQ(c.convexity(), v1::CURVE_CONVEXITY_CONCAVE);
  EXPECT_EQ(c.geometry().type(), v1::CURVE_GEOMETRY_TYPE_CIRCLE);
  EXPECT_DOUBLE_EQ(c.geometry().point().y(), 2.0);
  EXPECT_DOUBLE_EQ(c.geometry().direction().z(), 1.0);
  EXPECT_DOUBLE_EQ(c.geometry().radius(), 7.5);
  EXPECT_TRUE(c.geometry().analytic());
  EXPECT_DOUBLE_EQ(c.geometry().max_deviation(), 0.25);
  EXPECT_DOUBLE_EQ(c.length(), 47.1);

  ASSERT_EQ(p.loops_size(), 1);
  EXPECT_EQ(p.loops(0).region(), 2);
  EXPECT_EQ(p.loops(0).patch(), 1);
  EXPECT_EQ(p.loops(0).kind(), v1::LOOP_KIND_AXIAL);
  ASSERT_EQ(p.loops(0).curves_size(), 1);
  EXPECT_TRUE(p.loops(0).curves(0).reversed());

  ASSERT_EQ(p.corners_size(), 1);
  EXPECT_EQ(p.corners(0).vertex(), 9);
  EXPECT_DOUBLE_EQ(p.corners(0).position().x(), 3.0);
  EXPECT_TRUE(p.corners(0).snapped());
  EXPECT_THAT(p.corners(0).regions(), ElementsAre(-1, 1, 2));
  EXPECT_THAT(p.corners(0).curves(), ElementsAre(0, 0));

  ASSERT_EQ(p.adjacency_size(), 1);
  EXPECT_EQ(p.adjacency(0).region_a(), 1);
  EXPECT_EQ(p.adjacency(0).region_b(), 2);
  EXPECT_THAT(p.adjacency(0).curves(), ElementsAre(0));

  ASSERT_EQ(p.features_size(), 1);
  const v1::Feature& f = p.features(0);
  EXPECT_EQ(f.type(), v1::FEATURE_TYPE_FILLET_TORUS_CYLINDER_PLANE);
  EXPECT_THAT(f.regions(), ElementsAre(2, 1, 0));
  EXPECT_DOUBLE_EQ(f.radius(), 4.0);
  EXPECT_TRUE(f.convex());
  EXPECT_DOUBLE_EQ(f.direction().y(), 1.0);
  EXPECT_DOUBLE_EQ(f.point().z(), 5.0);

  EXPECT_THAT(p.point_labels(), ElementsAre(0, -1, 2));
}

TEST(TopologyToProto, JsonHasTheDesignKeys) {
  const absl::StatusOr<std::string> json = ResultJson(ToProto(OneOfEach()));
  ASSERT_TRUE(json.ok()) << json.status();
  for (const char* key : {"\"curves\":", "\"loops\":", "\"corners\":", "\"adjacency\":",
                          "\"features\":", "\"point_labels\":"}) {
    EXPECT_THAT(*json, HasSubstr(key));
  }
  EXPECT_THAT(*json, HasSubstr("\"FEATURE_TYPE_FILLET_TORUS_CYLINDER_PLANE\""));
  EXPECT_THAT(*json, HasSubstr("\"CURVE_GEOMETRY_TYPE_CIRCLE\""));
}

// plate_boss through RunPipeline, the JSON read back: its torus fillet
// (minor radius 4) is an FLT2 feature within 0.2 h, and the boundaries are
// there (issue 5 item 5).
TEST(TopologyToProto, PlateBossFilletSurvivesTheJsonRoundTrip) {
  const absl::StatusOr<GeneratedPart> part = GeneratePart("plate_boss", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  const std::string path = testing_files::ScratchPath("plate_boss.ply");
  ASSERT_TRUE(WriteMesh(part->mesh.tri, path).ok());
  const absl::StatusOr<PipelineResult> result = RunPipeline(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(result.ok()) << result.status();
  const absl::StatusOr<std::string> json = ResultJson(ToProto(*result));
  ASSERT_TRUE(json.ok()) << json.status();
  v1::SegmentationResult back;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(*json, &back).ok());
  EXPECT_EQ(back.curves_size(), static_cast<int>(result->topology.curves.size()));
  EXPECT_GT(back.curves_size(), 0);
  EXPECT_GT(back.loops_size(), 0);
  EXPECT_GT(back.corners_size(), 0);
  EXPECT_GT(back.adjacency_size(), 0);
  int flt2 = 0;
  for (const v1::Feature& f : back.features()) {
    const bool fillet = f.type() == v1::FEATURE_TYPE_FILLET_TORUS_CYLINDER_PLANE;
    if (fillet && std::abs(f.radius() - 4.0) <= 0.2) ++flt2;
  }
  EXPECT_GE(flt2, 1);
}

}  // namespace
}  // namespace meshseg
