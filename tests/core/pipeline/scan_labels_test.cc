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
// Of the chamfer's points, at least this share in its region: the points
// within the noise of a crease may go to either side (measured 0.947-0.973).
constexpr double kMinChamferCovered = 0.85;
// Genuine points the pipeline discards (outlier test) or leaves unlabelled.
constexpr double kMaxUnlabelledGenuine = 0.02;

// A scan of `part` written as XYZ, and the pipeline's result on that file
// (as `meshseg segment` reads it).
struct ScanResult {
  ScannedPart scan;
  PipelineResult result;
};
absl::StatusOr<ScanResult> ScanAndSegment(const std::string& part, const ScanParams& params) {
  absl::StatusOr<ScannedPart> scan = ScanPart(part, params);
  if (!scan.ok()) return scan.status();
  const std::string path = testing_files::ScratchPath(part + "_scan.xyz");
  if (absl::Status st = WritePointCloud(scan->cloud, path); !st.ok()) return st;
  absl::StatusOr<PipelineResult> r = RunPipeline(path);
  std::filesystem::remove(path);
  if (!r.ok()) return r.status();
  return ScanResult{.scan = *std::move(scan), .result = *std::move(r)};
}

// Expects the bars of issue 38 item 6 on `run`, scored by `e`; returns how
// many surfaces were checked for their type.
int ExpectLabelledAndTyped(const ScanResult& run, const testing::Evaluation& e) {
  EXPECT_GE(e.area_fraction, kMinPointAccuracy) << e;
  double seen = 0.0;
  for (const double a : run.scan.primitive_seen_area) seen += a;
  int typed = 0;
  for (const testing::PrimitiveScore& s : e.primitives) {
    if (run.scan.primitive_seen_area[s.primitive] < kMinTypedShare * seen) continue;
    ++typed;
    if (s.region < 0) {
      ADD_FAILURE() << s.name << ": no region";
      continue;
    }
    EXPECT_STREQ(SurfaceTypeName(run.result.regions[s.region].type), SurfaceTypeName(s.true_type))
        << s.name << " is mostly in a region of another type";
  }
  return typed;
}

TEST(RunPipelineOnScan, LabelsEachPointWithItsTrueSurface) {
  ScanParams params;
  params.points = kScanPoints;
  params.noise = kRangeNoise;
  params.outliers = kOutliers;
  const absl::StatusOr<ScanResult> run = ScanAndSegment("small_block", params);
  ASSERT_TRUE(run.ok()) << run.status();
  const ScannedPart& scan = run->scan;
  const PipelineResult* r = &run->result;
  ASSERT_EQ(r->point_labels.size(), scan.cloud.points.size());

  const testing::Evaluation e =
      testing::EvaluatePoints(scan, r->point_labels, static_cast<int>(r->regions.size()));
  EXPECT_GE(ExpectLabelledAndTyped(*run, e), 5) << "the block's seen planes and its bore";

  // The outlier count is the number of points labelled -1 for that reason:
  // at most all -1 labels, and nearly all genuine points are labelled.
  int64_t unlabelled = 0, genuine_unlabelled = 0, genuine = 0;
  for (size_t i = 0; i < r->point_labels.size(); ++i) {
    unlabelled += r->point_labels[i] < 0;
    if (scan.is_outlier[i]) continue;
    ++genuine;
    genuine_unlabelled += r->point_labels[i] < 0;
  }
  EXPECT_LE(r->point_outlier_count, unlabelled);
  EXPECT_LE(genuine_unlabelled, kMaxUnlabelledGenuine * genuine);
}

TEST(RunPipelineOnScan, AChamferBetweenTwoCreasesIsACone) {
  // A stepped shaft scanned at 40K points, range noise 0.3 spacings: its
  // 45-degree chamfer (1.3-1.4 % of the seen area, about 1000 points, 7
  // spacings wide) lies between a cylinder and the flat end face. The
  // reconstruction rounds both creases. The segmentation can grow one torus
  // over the chamfer and the end face (SplitOffPlanes gives the face back,
  // the rest a cone), and can type the chamfer's band a sphere: with the
  // rounded creases its mesh profile is an arc. On the points,
  // RetypeBesideNeighbours sets the neighbours' points aside on their own
  // surfaces and finds the cone. Two draws; measured over ten: the chamfer a
  // cone on ten (on main without these steps a torus on one and a sphere on
  // three), 98.8 % or more of the points labelled right, and of its points
  // 0.947-0.973 in its cone's region.
  ScanParams params;
  params.points = 40'000;
  params.noise = 0.3;
  for (const uint64_t seed : {2u, 3u}) {
    params.seed = seed;
    const absl::StatusOr<ScanResult> run = ScanAndSegment("stepped_shaft", params);
    ASSERT_TRUE(run.ok()) << run.status();
    const testing::Evaluation e = testing::EvaluatePoints(
        run->scan, run->result.point_labels, static_cast<int>(run->result.regions.size()));
    EXPECT_GE(ExpectLabelledAndTyped(*run, e), 6) << "the shaft's cylinders, faces and chamfer";
    const auto chamfer =
        std::find_if(e.primitives.begin(), e.primitives.end(),
                     [](const testing::PrimitiveScore& s) { return s.name == "chamfer"; });
    ASSERT_NE(chamfer, e.primitives.end());
    ASSERT_GE(chamfer->region, 0);
    EXPECT_EQ(run->result.regions[chamfer->region].type, SurfaceType::kCone) << "draw " << seed;
    EXPECT_GE(chamfer->covered, kMinChamferCovered) << "draw " << seed;
  }
}

TEST(RunPipelineOnScan, AFlatTopBesideATangentRoundIsAPlane) {
  // A plate with a boss scanned at 40K points, range noise 0.3 spacings: the
  // boss's flat top is an annulus (1.7-1.8 % of the seen area) between the
  // bore and a tangent edge round. The reconstructed mesh's resolution sets
  // th_dis (about 17 times the vertices' scatter), so with the data term in
  // units of th_dis / 3 a torus bent over the top missed it by 3.6 of that
  // scatter rms for less than the boundary through the smooth junction, and
  // the top went into the round's torus on every draw. In units of the
  // vertices' own scatter (SegmentParams::point_noise) the plane is cheaper.
  // Two draws, the top a torus on both before (and on draws 2 and 4);
  // measured over four, a plane on all (bench/segment/scan_regions).
  ScanParams params;
  params.points = 40'000;
  params.noise = 0.3;
  for (const uint64_t seed : {1u, 3u}) {
    params.seed = seed;
    const absl::StatusOr<ScanResult> run = ScanAndSegment("plate_boss", params);
    ASSERT_TRUE(run.ok()) << run.status();
    const testing::Evaluation e = testing::EvaluatePoints(
        run->scan, run->result.point_labels, static_cast<int>(run->result.regions.size()));
    const auto top =
        std::find_if(e.primitives.begin(), e.primitives.end(),
                     [](const testing::PrimitiveScore& s) { return s.name == "boss_top"; });
    ASSERT_NE(top, e.primitives.end());
    ASSERT_GE(top->region, 0);
    EXPECT_EQ(run->result.regions[top->region].type, SurfaceType::kPlane) << "draw " << seed;
    EXPECT_GE(ExpectLabelledAndTyped(*run, e), 10) << "draw " << seed;
  }
}

}  // namespace
}  // namespace meshseg
