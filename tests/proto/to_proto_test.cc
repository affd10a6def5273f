#include "meshseg/proto/convert.h"

#include <gtest/gtest.h>

namespace meshseg {
namespace {

PipelineResult TwoRegions() {
  PipelineResult r;
  r.mesh.vertex_count = 5;
  r.mesh.input_face_count = 4;
  r.mesh.face_count = 3;
  r.mesh.dropped_face_count = 1;
  r.mesh.mean_edge_length = 0.25;
  r.mesh.bbox_max = {1, 2, 3};
  r.face_labels = {0, -1, 1, 1};
  r.vertex_labels = {0, 0, 1, 1, -1};
  Region plane;
  plane.id = 0;
  plane.type = SurfaceType::kPlane;
  plane.surface = Plane{.point = {0, 0, 1}, .normal = {0, 0, -1}};
  plane.face_count = 1;
  plane.rms_distance = 0.01;
  Region cyl;
  cyl.id = 1;
  cyl.type = SurfaceType::kCylinder;
  cyl.surface = Cylinder{.axis_origin = {1, 1, 0}, .axis_direction = {0, 1, 0}, .radius = 2.5};
  cyl.face_count = 2;
  cyl.area = 7.0;
  r.regions = {plane, cyl};
  r.estimates.noise_sigma = 0.002;
  r.estimates.angle_tolerance_deg = 5.0;
  r.remesh_edge_length = 0.25;
  r.remesh_face_count = 1234;
  r.remesh_fine_edge_length = 0.125;
  return r;
}

TEST(ToProto, KeepsLabelsInInputOrder) {
  const v1::SegmentationResult p = ToProto(TwoRegions());
  ASSERT_EQ(p.face_labels_size(), 4);
  EXPECT_EQ(p.face_labels(0), 0);
  EXPECT_EQ(p.face_labels(1), -1);
  EXPECT_EQ(p.face_labels(3), 1);
  ASSERT_EQ(p.vertex_labels_size(), 5);
  EXPECT_EQ(p.vertex_labels(4), -1);
}

TEST(ToProto, ReportsInputFaceCountAndMeshInfo) {
  const v1::SegmentationResult p = ToProto(TwoRegions());
  EXPECT_EQ(p.mesh().face_count(), 4);  // faces of the input file
  EXPECT_EQ(p.mesh().mesh_face_count(), 3);
  EXPECT_EQ(p.mesh().vertex_count(), 5);
  EXPECT_EQ(p.mesh().dropped_face_count(), 1);
  EXPECT_DOUBLE_EQ(p.mesh().mean_edge_length(), 0.25);
  EXPECT_DOUBLE_EQ(p.mesh().bbox_max().z(), 3.0);
}

TEST(ToProto, FillsTheSurfaceOfEachRegion) {
  const v1::SegmentationResult p = ToProto(TwoRegions());
  ASSERT_EQ(p.regions_size(), 2);
  EXPECT_EQ(p.regions(0).type(), v1::SURFACE_TYPE_PLANE);
  ASSERT_TRUE(p.regions(0).has_plane());
  EXPECT_DOUBLE_EQ(p.regions(0).plane().normal().z(), -1.0);
  EXPECT_EQ(p.regions(1).type(), v1::SURFACE_TYPE_CYLINDER);
  ASSERT_TRUE(p.regions(1).has_cylinder());
  EXPECT_DOUBLE_EQ(p.regions(1).cylinder().radius(), 2.5);
  EXPECT_DOUBLE_EQ(p.regions(1).cylinder().axis_direction().y(), 1.0);
  EXPECT_EQ(p.regions(1).face_count(), 2);
  EXPECT_DOUBLE_EQ(p.regions(1).area(), 7.0);
  EXPECT_DOUBLE_EQ(p.estimates().angle_tolerance_deg(), 5.0);
  EXPECT_DOUBLE_EQ(p.estimates().remesh_edge_length(), 0.25);
  EXPECT_EQ(p.estimates().remesh_face_count(), 1234);
  EXPECT_DOUBLE_EQ(p.estimates().remesh_fine_edge_length(), 0.125);
}

TEST(ToProto, WritesTenQuadricCoefficients) {
  PipelineResult r;
  Region q;
  q.type = SurfaceType::kQuadric;
  Quadric quadric;
  for (int i = 0; i < 10; ++i) quadric.c[i] = i;
  q.surface = quadric;
  r.regions = {q};
  const v1::SegmentationResult p = ToProto(r);
  ASSERT_TRUE(p.regions(0).has_quadric());
  ASSERT_EQ(p.regions(0).quadric().coefficients_size(), 10);
  EXPECT_DOUBLE_EQ(p.regions(0).quadric().coefficients(9), 9.0);
}

// The exact path's additions: the surfaces (the regions on each, their joint
// fit), each region's surface_id, and the path, tolerance and share.
TEST(ToProto, CarriesSharedSurfacesAndTheExactPath) {
  PipelineResult r = TwoRegions();
  r.regions[0].surface_id = 0;
  r.regions[1].surface_id = 0;  // as if both lay on one surface
  r.surfaces.push_back({.id = 0,
                        .type = SurfaceType::kPlane,
                        .surface = Plane{.point = {0, 0, 2}, .normal = {0, 0, 1}},
                        .regions = {0, 1},
                        .rms_distance = 1e-9,
                        .max_distance = 2e-9});
  r.estimates.path = SegmentationPath::kExactFacets;
  r.estimates.exact_tolerance = 8e-5;
  r.estimates.exact_share = 0.995;
  const v1::SegmentationResult p = ToProto(r);
  ASSERT_EQ(p.surfaces_size(), 1);
  EXPECT_EQ(p.surfaces(0).type(), v1::SURFACE_TYPE_PLANE);
  EXPECT_EQ(p.surfaces(0).plane().point().z(), 2.0);
  EXPECT_EQ(p.surfaces(0).regions_size(), 2);
  EXPECT_EQ(p.surfaces(0).max_distance(), 2e-9);
  EXPECT_EQ(p.regions(1).surface_id(), 0);
  EXPECT_EQ(p.estimates().segmentation_path(), v1::SEGMENTATION_PATH_EXACT_FACETS);
  EXPECT_EQ(p.estimates().exact_tolerance(), 8e-5);
  EXPECT_EQ(p.estimates().exact_share(), 0.995);
}

}  // namespace
}  // namespace meshseg
