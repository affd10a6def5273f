// FromProto(SegmentationResult): a result printed as JSON and parsed back
// gives the regions, estimates and topology it was made of; a message that
// is not a valid result is refused naming what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

PipelineResult Sample() {
  PipelineResult r;
  r.mesh.vertex_count = 12;
  r.mesh.input_face_count = 5;
  r.mesh.face_count = 5;
  r.mesh.mean_edge_length = 0.5;
  r.face_labels = {0, 1, 1, -1, 2};
  r.regions = {
      Region{.id = 0, .type = SurfaceType::kPlane, .surface = Plane{{0, 0, 1}, {0, 0, 1}}},
      Region{.id = 1,
             .type = SurfaceType::kCone,
             .surface = Cone{{1, 2, 3}, {0, 1, 0}, 0.3},
             .face_count = 2,
             .rms_distance = 0.01},
      Region{.id = 2,
             .type = SurfaceType::kFreeform,
             .surface = Quadric{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}}},
  };
  r.estimates.noise_sigma = 0.02;
  BoundaryCurve c;
  c.id = 0;
  c.vertices = {3, 4, 5};
  c.left_region = 0;
  c.right_region = 1;
  c.start_corner = 0;
  c.end_corner = 0;
  c.geometry = {.type = CurveGeometryType::kLine, .point = {1, 0, 0}, .direction = {0, 1, 0}};
  c.junction_artifact = true;
  r.topology.curves.push_back(c);
  r.topology.loops.push_back(
      Loop{.id = 0, .region = 1, .patch = 2, .kind = LoopKind::kInner, .curves = {{0, true}}});
  r.topology.corners.push_back(Corner{
      .id = 0, .vertex = 3, .cluster = 0, .position = {1, 1, 1}, .regions = {0, 1}, .curves = {0}});
  r.topology.adjacency.push_back(Adjacency{.region_a = 0, .region_b = 1, .curves = {0}});
  return r;
}

TEST(ResultFromProto, JsonRoundTripGivesTheCoreResultBack) {
  const absl::StatusOr<std::string> json = ResultJson(ToProto(Sample()));
  ASSERT_TRUE(json.ok()) << json.status();
  const absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(*json);
  ASSERT_TRUE(message.ok()) << message.status();
  const absl::StatusOr<PipelineResult> back = FromProto(*message);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->face_labels, Sample().face_labels);
  ASSERT_EQ(back->regions.size(), 3u);
  EXPECT_EQ(back->regions[1].type, SurfaceType::kCone);
  EXPECT_DOUBLE_EQ(std::get<Cone>(back->regions[1].surface).half_angle, 0.3);
  EXPECT_DOUBLE_EQ(back->regions[1].rms_distance, 0.01);
  EXPECT_EQ(back->regions[2].type, SurfaceType::kFreeform);
  EXPECT_DOUBLE_EQ(std::get<Quadric>(back->regions[2].surface).c[9], 10.0);
  EXPECT_DOUBLE_EQ(back->estimates.noise_sigma, 0.02);
  ASSERT_EQ(back->topology.curves.size(), 1u);
  EXPECT_EQ(back->topology.curves[0].vertices, (std::vector<int>{3, 4, 5}));
  EXPECT_TRUE(back->topology.curves[0].junction_artifact);
  EXPECT_EQ(back->topology.curves[0].geometry.type, CurveGeometryType::kLine);
  ASSERT_EQ(back->topology.loops.size(), 1u);
  EXPECT_EQ(back->topology.loops[0].kind, LoopKind::kInner);
  EXPECT_TRUE(back->topology.loops[0].curves[0].reversed);
  // Patch counts come from the loops (the message has no RegionTopology).
  ASSERT_EQ(back->topology.regions.size(), 3u);
  EXPECT_EQ(back->topology.regions[1].patch_count, 3);
  EXPECT_EQ(back->topology.regions[1].loops, (std::vector<int>{0}));
  EXPECT_EQ(back->topology.corners[0].regions, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(back->topology.mean_edge_length, 0.5);
}

TEST(ResultFromProto, InvalidMessagesNameTheProblem) {
  const v1::SegmentationResult good = ToProto(Sample());
  v1::SegmentationResult m = good;
  m.mutable_regions(1)->clear_cone();
  absl::Status s = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("region 1"));

  m = good;
  m.mutable_regions(2)->mutable_quadric()->mutable_coefficients()->RemoveLast();
  s = FromProto(m).status();
  EXPECT_THAT(s.message(), HasSubstr("9 coefficients"));

  m = good;
  m.mutable_loops(0)->mutable_curves(0)->set_curve(7);
  s = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("curve 7"));

  m = good;
  m.mutable_curves(0)->set_right_region(5);
  s = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("curve 0"));
}

// The mesh the ids index and the length unit survive the JSON round trip;
// ids outside the mesh or the input faces are refused, naming them.
TEST(ResultFromProto, MeshGeometryAndLengthUnitRoundTrip) {
  PipelineResult r = Sample();
  r.length_unit = "in";
  r.mesh_geometry = MeshGeometry{
      .vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.25}, {1, 1, 0}},
      .faces = {{0, 1, 2}, {2, 1, 3}},
      .input_face = {0, 4},
  };
  const absl::StatusOr<std::string> json = ResultJson(ToProto(r));
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_THAT(*json, HasSubstr("\"length_unit\":\"in\""));
  const absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(*json);
  ASSERT_TRUE(message.ok()) << message.status();
  EXPECT_EQ(message->mesh_geometry().vertices_size(), 12);
  const absl::StatusOr<PipelineResult> back = FromProto(*message);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->length_unit, "in");
  ASSERT_TRUE(back->mesh_geometry.has_value());
  EXPECT_EQ(back->mesh_geometry->vertices, r.mesh_geometry->vertices);
  EXPECT_EQ(back->mesh_geometry->faces, r.mesh_geometry->faces);
  EXPECT_EQ(back->mesh_geometry->input_face, r.mesh_geometry->input_face);
  EXPECT_FALSE(FromProto(ToProto(Sample()))->mesh_geometry.has_value()) << "only when asked";

  v1::SegmentationResult m = ToProto(r);
  m.mutable_mesh_geometry()->set_faces(4, 9);
  absl::Status bad = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_THAT(bad.message(), HasSubstr("face 1 has vertex id 9, outside [0, 4)"));
  m = ToProto(r);
  m.mutable_mesh_geometry()->set_input_faces(1, 5);  // 5 input faces
  bad = FromProto(m).status();
  EXPECT_THAT(bad.message(), HasSubstr("face 1 has input face 5, outside [0, 5)"));
  m = ToProto(r);
  m.mutable_mesh_geometry()->add_vertices(1.0);
  bad = FromProto(m).status();
  EXPECT_THAT(bad.message(), HasSubstr("3 numbers per element"));
}

// Issue 38: which reconstructed faces close an unsupported area, and how much.
TEST(ResultFromProto, FilledFacesAndAreaRoundTrip) {
  PipelineResult r = Sample();
  r.face_filled.assign(r.face_labels.size(), 0);
  r.face_filled[1] = r.face_filled.back() = 1;
  r.filled_face_count = 2;
  r.filled_area = 0.375;
  const absl::StatusOr<std::string> json = ResultJson(ToProto(r));
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_THAT(*json, HasSubstr("\"filled_face_count\":\"2\""));
  EXPECT_THAT(*json, HasSubstr("\"filled_area\":0.375"));
  EXPECT_THAT(*json, HasSubstr("\"face_filled\":[false,true,"));
  const absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(*json);
  ASSERT_TRUE(message.ok()) << message.status();
  const absl::StatusOr<PipelineResult> back = FromProto(*message);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->face_filled, r.face_filled);
  EXPECT_EQ(back->filled_face_count, 2);
  EXPECT_EQ(back->filled_area, 0.375);
  EXPECT_TRUE(FromProto(ToProto(Sample()))->face_filled.empty()) << "a mesh input has none";

  v1::SegmentationResult m = ToProto(r);
  m.add_face_filled(true);
  const absl::Status bad = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_THAT(bad.message(), HasSubstr("face_filled has 6 entries for 5 faces"));
}

// Point-cloud input: one label per input point and how many of them the
// outlier test discarded, through the JSON and back; a count beyond the
// points is refused naming both.
TEST(ResultFromProto, PointLabelsAndOutlierCountRoundTrip) {
  PipelineResult r = Sample();
  r.from_point_cloud = true;
  r.point_count = 5;
  r.point_labels = {0, -1, 1, -1, 0};
  r.point_outlier_count = 2;
  const absl::StatusOr<std::string> json = ResultJson(ToProto(r));
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_THAT(*json, HasSubstr("\"point_labels\":[0,-1,1,-1,0]"));
  EXPECT_THAT(*json, HasSubstr("\"point_outlier_count\":\"2\""));
  const absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(*json);
  ASSERT_TRUE(message.ok()) << message.status();
  const absl::StatusOr<PipelineResult> back = FromProto(*message);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_TRUE(back->from_point_cloud);
  EXPECT_EQ(back->point_count, 5);
  EXPECT_EQ(back->point_labels, r.point_labels);
  EXPECT_EQ(back->point_outlier_count, 2);
  EXPECT_EQ(FromProto(ToProto(Sample()))->point_outlier_count, 0) << "a mesh input has none";

  v1::SegmentationResult m = ToProto(r);
  m.set_point_outlier_count(6);
  const absl::Status bad = FromProto(m).status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_THAT(bad.message(), HasSubstr("point_outlier_count 6 outside [0, 5]"));
}

TEST(ParseResultJson, MalformedJsonIsInvalidArgument) {
  const absl::Status s = ParseResultJson("{\"regions\": [ {\"id\": ").status();
  EXPECT_TRUE(absl::IsInvalidArgument(s)) << s;
  EXPECT_THAT(s.message(), HasSubstr("result json"));
}

}  // namespace
}  // namespace meshseg
