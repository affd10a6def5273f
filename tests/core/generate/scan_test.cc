// The scanner mode of the generator (ScanPart): point counts and outlier
// flags, occlusion (faces turned away from every view get no points), range
// noise along the ray, and bad parameters.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
