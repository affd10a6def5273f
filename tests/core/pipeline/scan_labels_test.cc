// RunPipeline on a simulated laser scan (ScanPart: four views from above, so
// occlusion and uneven density, range noise, uniform outliers): every input
// point gets the region of its nearest reconstructed face, scored against
// the scan's truth (the primitive each point was drawn from) with the
// segment tests' majority matching (segment_eval.h, EvaluatePoints).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/point_cloud.h"
#include "scratch_dir.h"
#include "segment_eval.h"

namespace meshseg {
namespace {

// A small scan, so the test stays well under a second of pipeline time.
constexpr int64_t kScanPoints = 6000;
constexpr double kRangeNoise = 0.1;  // spacings
constexpr double kOutliers = 0.02;   // of the scan points, uniform in the box
// The bars of issue 38 item 6: at least 95 % of the genuine points carry
// their own surface's region (points within noise of an edge between two
// surfaces can go either way: on this scan about 1 % lie within a spacing
// of one; measured 98.8-99.3 % over draws 1-10), and every surface seen over
// at least 1 % of the seen area has a majority region of its type. The
// block's bore, seen from above, is a band from its rim down as far as the
// views reach into it: the reconstruction may type it as a sphere of the
// bore's radius, which meets the band near the rim only (over a depth d it
// leaves the cylinder by about d^2 / (2R)); on the band's own points the
// cylinder fits at the noise and the sphere does not, and the type is
// decided again there (RetypeToPoints). Measured over draws 1-10: the bore
// a cylinder and every plane its own on all ten (bench/segment/scan_regions
// measures more parts and draws).
constexpr double kMinPointAccuracy = 0.95;
constexpr double kMinTypedShare = 0.01;
// Genuine points the pipeline discards (outlier test) or leaves unlabelled.
constexpr double kMaxUnlabelledGenuine = 0.02;

TEST(RunPipelineOnScan, LabelsEachPointWithItsTrueSurface) {
  ScanParams params;
  params.points = kScanPoints;
  params.noise = kRangeNoise;
  params.outliers = kOutliers;
  const absl::StatusOr<ScannedPart> scan = ScanPart("small_block", params);
  ASSERT_TRUE(scan.ok()) << scan.status();
  const std::string path = testing_files::ScratchPath("small_block_scan.xyz");
  ASSERT_TRUE(WritePointCloud(scan->cloud, path).ok());
  const absl::StatusOr<PipelineResult> r = RunPipeline(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_EQ(r->point_labels.size(), scan->cloud.points.size());

  const testing::Evaluation e =
      testing::EvaluatePoints(*scan, r->point_labels, static_cast<int>(r->regions.size()));
  EXPECT_GE(e.area_fraction, kMinPointAccuracy) << e;

  double seen = 0.0;
  for (const double a : scan->primitive_seen_area) seen += a;
  int typed = 0;
  for (const testing::PrimitiveScore& s : e.primitives) {
    if (scan->primitive_seen_area[s.primitive] < kMinTypedShare * seen) continue;
    ASSERT_GE(s.region, 0) << s.name << ": no region";
    EXPECT_STREQ(SurfaceTypeName(r->regions[s.region].type), SurfaceTypeName(s.true_type))
        << s.name << " is mostly in a region of another type";
    ++typed;
  }
  EXPECT_GE(typed, 5) << "the block's seen planes and its bore";

  // The outlier count is the number of points labelled -1 for that reason:
  // at most all -1 labels, and nearly all genuine points are labelled.
  int64_t unlabelled = 0, genuine_unlabelled = 0, genuine = 0;
  for (size_t i = 0; i < r->point_labels.size(); ++i) {
    unlabelled += r->point_labels[i] < 0;
    if (scan->is_outlier[i]) continue;
    ++genuine;
    genuine_unlabelled += r->point_labels[i] < 0;
  }
  EXPECT_LE(r->point_outlier_count, unlabelled);
  EXPECT_LE(genuine_unlabelled, kMaxUnlabelledGenuine * genuine);
}

}  // namespace
}  // namespace meshseg
