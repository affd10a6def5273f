// The scanner mode of the generator (ScanPart): point counts and outlier
// flags, occlusion (faces turned away from every view get no points), range
// noise along the ray, and bad parameters.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "meshseg/generate.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

ScanParams Small() {
  ScanParams p;
  p.points = 3000;
  p.normals = true;
  return p;
}

TEST(ScanPart, CountsPointsAndFlagsTheOutliers) {
  ScanParams p = Small();
  p.outliers = 0.05;
  const auto scan = ScanPart("small_block", p);
  ASSERT_TRUE(scan.ok()) << scan.status();
  ASSERT_EQ(scan->cloud.points.size(), 3150u);
  ASSERT_EQ(scan->is_outlier.size(), 3150u);
  ASSERT_EQ(scan->point_primitive.size(), 3150u);
  EXPECT_EQ(std::count(scan->is_outlier.begin(), scan->is_outlier.end(), 1), 150);
  for (size_t i = 3000; i < 3150; ++i) EXPECT_EQ(scan->point_primitive[i], -1);
  EXPECT_GT(scan->spacing, 0.0);
}

// The views look down at 35 degrees: a face whose outward normal points
// straight down is seen by none, and part of the surface goes unseen.
TEST(ScanPart, FacesTurnedAwayFromEveryViewGetNoPoints) {
  const auto scan = ScanPart("small_block", Small());
  ASSERT_TRUE(scan.ok()) << scan.status();
  int64_t down = 0;
  for (const auto& n : scan->cloud.normals) down += n.z() < -0.99;
  EXPECT_EQ(down, 0);
  EXPECT_LT(scan->seen_area_fraction, 0.95);
  EXPECT_GT(scan->seen_area_fraction, 0.3);
}

// Without noise every point lies on a primitive of the part (within the
// voxel mesh's distance to its exact surface); range noise moves points off
// it by about `noise` spacings.
TEST(ScanPart, RangeNoiseMovesPointsOffTheSurfaceByItsSigma) {
  ScanParams clean = Small();
  clean.noise = 0.0;
  ScanParams noisy = clean;
  noisy.noise = 0.5;
  const auto a = ScanPart("small_block", clean);
  const auto b = ScanPart("small_block", noisy);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->cloud.points.size(), b->cloud.points.size());
  // Same seed: the same surface points, moved along their rays.
  double sum2 = 0.0;
  for (size_t i = 0; i < a->cloud.points.size(); ++i) {
    sum2 += (b->cloud.points[i] - a->cloud.points[i]).squaredNorm();
  }
  const double rms = std::sqrt(sum2 / a->cloud.points.size());
  EXPECT_NEAR(rms, 0.5 * b->spacing, 0.1 * b->spacing);
}

// The seen area per primitive comes from the same uniform draw as the seen
// fraction: it adds up to that fraction of the surface, is zero for the
// bottom (no view from above sees it; the part is tilted 17 degrees, less
// than the views' 35 degree elevation) and close to the whole area for the
// top, which every view sees unoccluded (10 %: the draw's sampling error on
// a face of a quarter of the surface is about 2 %).
TEST(ScanPart, SeenAreaPerPrimitiveAddsUpToTheSeenFraction) {
  const auto scan = ScanPart("small_block", Small());
  ASSERT_TRUE(scan.ok()) << scan.status();
  const GeneratedPart& part = scan->part;
  ASSERT_EQ(scan->primitive_seen_area.size(), part.primitives.size());
  std::vector<double> area(part.primitives.size(), 0.0);
  double total = 0.0, without = 0.0;  // faces of no primitive count in the fraction only
  for (size_t f = 0; f < part.face_primitive.size(); ++f) {
    const double a = part.mesh.tri.calc_face_area(TriMesh::FaceHandle(static_cast<int>(f)));
    total += a;
    if (part.face_primitive[f] >= 0) area[part.face_primitive[f]] += a;
    if (part.face_primitive[f] < 0) without += a;
  }
  double seen = 0.0;
  for (const double a : scan->primitive_seen_area) seen += a;
  EXPECT_NEAR(seen, scan->seen_area_fraction * total, without + 1e-9 * total);
  for (const PrimitiveTruth& t : part.primitives) {
    if (t.name == "bottom") EXPECT_EQ(scan->primitive_seen_area[t.id], 0.0);
    if (t.name == "top") EXPECT_NEAR(scan->primitive_seen_area[t.id], area[t.id], 0.1 * area[t.id]);
  }
}

TEST(ScanPart, BadParametersAreInvalidNamingTheValue) {
  ScanParams p = Small();
  p.views = 0;
  EXPECT_THAT(ScanPart("small_block", p).status().message(), HasSubstr("views 0 must be >= 1"));
  p = Small();
  p.noise = -1;
  EXPECT_THAT(ScanPart("small_block", p).status().message(), HasSubstr("noise -1 must be >= 0"));
  p = Small();
  p.elevation_deg = 90;
  EXPECT_THAT(ScanPart("small_block", p).status().message(), HasSubstr("elevation_deg 90"));
  EXPECT_EQ(ScanPart("no_such_part", Small()).status().code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace meshseg
