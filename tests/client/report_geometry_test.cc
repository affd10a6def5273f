// GeometryForReport: the segmented file as the report's buffers, each face
// or point labelled with its region's index, curves as segments, and a clear
// error when the file is not the one the result describes.
#include "client/report_geometry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "tests/server/test_files.h"

namespace meshseg::cli {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Regions with ids 7 and 3 (index 0 and 1): labels map ids to indices.
v1::SegmentationResult TwoRegions(int face_count) {
  v1::SegmentationResult result;
  result.add_regions()->set_id(7);
  result.add_regions()->set_id(3);
  for (int i = 0; i < face_count; ++i) result.add_face_labels(i % 2 == 0 ? 7 : 3);
  return result;
}

TEST(GeometryForReport, MeshFacesTakeTheirInputFacesRegionIndex) {
  testing_files::TestMesh box = testing_files::SplitBox(1, {2.0, 4.0, 6.0});
  const int kept = static_cast<int>(box.f.size());
  box.f.push_back({0, 0, 1});  // degenerate: dropped while loading
  const std::string path = testing_files::ScratchPath("box.off");
  testing_files::WriteOff(box, path);
  v1::SegmentationResult result = TwoRegions(kept + 1);
  result.set_face_labels(kept, -1);
  v1::BoundaryCurve* curve = result.add_curves();
  curve->set_sharp(true);
  for (const int v : {0, 1, 2}) curve->add_vertices(v);

  const absl::StatusOr<ReportGeometry> g = GeometryForReport(path, result, std::nullopt);
  ASSERT_TRUE(g.ok()) << g.status();
  EXPECT_EQ(g->kind, ReportGeometry::Kind::kTriangles);
  ASSERT_EQ(g->labels.size(), static_cast<std::size_t>(kept)) << "one per mesh face";
  for (int i = 0; i < kept; ++i) EXPECT_EQ(g->labels[i], i % 2 == 0 ? 0 : 1) << "face " << i;
  EXPECT_EQ(g->triangles.size(), 3u * kept);
  EXPECT_EQ(g->positions.size(), 3 * box.v.size());
  EXPECT_THAT(g->offset, ElementsAre(1.0, 2.0, 3.0)) << "the bounding box centre";
  EXPECT_FLOAT_EQ(g->positions[0], -1.0f) << "vertex 0 at the origin, minus the centre";
  EXPECT_THAT(g->sharp_segments, ElementsAre(0u, 1u, 1u, 2u));
  EXPECT_TRUE(g->smooth_segments.empty());
}

TEST(GeometryForReport, AnotherFileIsAnErrorNamingIt) {
  const std::string path = testing_files::ScratchPath("other.off");
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const absl::StatusOr<ReportGeometry> g = GeometryForReport(path, TwoRegions(5), std::nullopt);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(g.status().message(),
              AllOf(HasSubstr("other.off"), HasSubstr("12 faces"), HasSubstr("5 face labels")));

  v1::SegmentationResult result = TwoRegions(12);
  result.add_curves()->add_vertices(99);
  const absl::StatusOr<ReportGeometry> c = GeometryForReport(path, result, std::nullopt);
  ASSERT_FALSE(c.ok());
  EXPECT_THAT(c.status().message(), AllOf(HasSubstr("vertex 99"), HasSubstr("8 vertices")));
}

TEST(GeometryForReport, PointCloudPointsTakeTheirPointLabels) {
  const testing_files::TestMesh box = testing_files::SplitBox(1, {1, 1, 1});
  const std::string path = testing_files::ScratchPath("points.xyz");
  testing_files::WriteXyz(box, path);
  v1::SegmentationResult result = TwoRegions(0);
  for (std::size_t i = 0; i < box.v.size(); ++i) result.add_point_labels(i == 0 ? -1 : 3);
  const absl::StatusOr<ReportGeometry> g = GeometryForReport(path, result, std::nullopt);
  ASSERT_TRUE(g.ok()) << g.status();
  EXPECT_EQ(g->kind, ReportGeometry::Kind::kPoints);
  EXPECT_TRUE(g->triangles.empty());
  ASSERT_EQ(g->labels.size(), box.v.size());
  EXPECT_EQ(g->labels[0], -1);
  EXPECT_EQ(g->labels[1], 1);
  EXPECT_THAT(g->note, HasSubstr("reconstructed mesh"));

  result.add_point_labels(3);
  const absl::StatusOr<ReportGeometry> bad = GeometryForReport(path, result, std::nullopt);
  ASSERT_FALSE(bad.ok());
  EXPECT_THAT(bad.status().message(), AllOf(HasSubstr("points.xyz"), HasSubstr("9 point labels")));
}

TEST(GeometryForReport, MissingFileIsNotFound) {
  const absl::StatusOr<ReportGeometry> g =
      GeometryForReport(testing_files::ScratchPath("missing.stl"), TwoRegions(1), std::nullopt);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(g.status().message(), HasSubstr("missing.stl"));
}

}  // namespace
}  // namespace meshseg::cli
