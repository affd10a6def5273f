// Region.subdivision (#35): a freeform region's control mesh printed as the
// result JSON and parsed back is the same control mesh; a message whose
// arrays do not describe one is refused naming the region and the array.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

// Two regions; the second is freeform and carries a control mesh: a
// tetrahedron with one sharp edge and one corner.
PipelineResult WithSubdivision() {
  PipelineResult r;
  r.mesh.vertex_count = 4;
  r.mesh.input_face_count = 4;
  r.mesh.face_count = 4;
  r.face_labels = {0, 1, 1, 1};
  r.regions = {
      Region{.id = 0, .type = SurfaceType::kPlane, .surface = Plane{{0, 0, 0}, {0, 0, 1}}},
      Region{.id = 1,
             .type = SurfaceType::kFreeform,
             .surface = Quadric{{1, 1, 1, 0, 0, 0, 0, 0, 0, -1}},
             .face_count = 3},
  };
  RegionSubdivision s;
  s.region = 1;
  s.control.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.5, 1.5}};
  s.control.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  s.control.creases = {{0, 1}};
  s.control.corners = {3};
  s.rms_distance = 0.125;
  s.max_distance = 0.5;
  r.subdivisions.push_back(s);
  return r;
}

TEST(SubdivisionProto, JsonRoundTripGivesTheControlMeshBack) {
  const absl::StatusOr<std::string> json = ResultJson(ToProto(WithSubdivision()));
  ASSERT_TRUE(json.ok()) << json.status();
  // The new key sits in the region; the region keeps its quadric.
  EXPECT_THAT(*json, HasSubstr("\"subdivision\""));
  EXPECT_THAT(*json, HasSubstr("\"quadric\""));
  const absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(*json);
  ASSERT_TRUE(message.ok()) << message.status();
  EXPECT_FALSE(message->regions(0).has_subdivision());
  ASSERT_TRUE(message->regions(1).has_subdivision());
  EXPECT_EQ(message->regions(1).subdivision().vertices_size(), 12);
  const absl::StatusOr<PipelineResult> back = FromProto(*message);
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_EQ(back->subdivisions.size(), 1u);
  const PipelineResult sample = WithSubdivision();
  const RegionSubdivision& want = sample.subdivisions[0];
  const RegionSubdivision& got = back->subdivisions[0];
  EXPECT_EQ(got.region, 1);
  ASSERT_EQ(got.control.vertices.size(), want.control.vertices.size());
  for (size_t v = 0; v < want.control.vertices.size(); ++v) {
    EXPECT_EQ(got.control.vertices[v], want.control.vertices[v]) << v;
  }
  EXPECT_EQ(got.control.faces, want.control.faces);
  EXPECT_EQ(got.control.creases, want.control.creases);
  EXPECT_EQ(got.control.corners, want.control.corners);
  EXPECT_EQ(got.rms_distance, 0.125);
  EXPECT_EQ(got.max_distance, 0.5);
}

TEST(SubdivisionProto, ArraysThatAreNoControlMeshAreRefused) {
  const v1::SegmentationResult good = ToProto(WithSubdivision());
  {
    v1::SegmentationResult m = good;
    m.mutable_regions(1)->mutable_subdivision()->set_faces(4, 7);  // 4 vertices
    const absl::StatusOr<PipelineResult> r = FromProto(m);
    ASSERT_FALSE(r.ok());
    EXPECT_THAT(r.status().message(), HasSubstr("region 1 subdivision faces id 7"));
  }
  {
    v1::SegmentationResult m = good;
    m.mutable_regions(1)->mutable_subdivision()->add_creases(2);  // half a pair
    const absl::StatusOr<PipelineResult> r = FromProto(m);
    ASSERT_FALSE(r.ok());
    EXPECT_THAT(r.status().message(), HasSubstr("creases has 3 ids, not a multiple of 2"));
  }
  {
    v1::SegmentationResult m = good;
    m.mutable_regions(1)->mutable_subdivision()->add_vertices(1.0);
    const absl::StatusOr<PipelineResult> r = FromProto(m);
    ASSERT_FALSE(r.ok());
    EXPECT_THAT(r.status().message(), HasSubstr("vertices has 13 numbers"));
  }
  {
    v1::SegmentationResult m = good;
    m.mutable_regions(1)->mutable_subdivision()->set_vertices(4, std::nan(""));
    const absl::StatusOr<PipelineResult> r = FromProto(m);
    ASSERT_FALSE(r.ok());
    EXPECT_THAT(r.status().message(), HasSubstr("subdivision vertex 1 is not finite"));
  }
}

}  // namespace
}  // namespace meshseg
