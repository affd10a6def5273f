// Reconstruction of the real point clouds in shared/data, compared with their
// ground-truth meshes (SOURCES.md there).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "clouds.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/reconstruct.h"
#include "surface_metrics.h"

namespace meshseg {
namespace {

std::string DataPath(const std::string& name) {
  return std::string(MESHSEG_SHARED_DATA_DIR) + "/" + name;
}

struct Case {
  const char* cloud;
  const char* truth;
  ReconstructParams params;
  // Bounds on the distances, in point spacings, from area samples of the
  // reconstruction to the truth (accuracy) and of the truth to the
  // reconstruction (completeness).
  double max_median;
  double max_p95;
};

void CheckAgainstTruth(const Case& c) {
  const auto cloud = ReadPointCloud(DataPath(c.cloud));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  const auto truth = ReadMesh(DataPath(c.truth));
  ASSERT_TRUE(truth.ok()) << truth.status();
  const auto r = Reconstruct(*cloud, c.params);
  ASSERT_TRUE(r.ok()) << r.status();
  const TriMesh& m = r->mesh.tri;
  const double h = r->stats.point_spacing;
  EXPECT_EQ(test::BoundaryEdgeCount(m), 0);
  EXPECT_EQ(test::NonManifoldVertexCount(m), 0);
  EXPECT_EQ(test::ComponentCount(m), 1);
  constexpr int kSamples = 1000;
  const std::vector<test::Triangle> ours = test::Triangles(m), theirs = test::Triangles(truth->tri);
  const auto accuracy =
      test::SortedDistances(test::AreaSamples(ours, kSamples), test::SurfaceDistance(theirs));
  const auto completeness =
      test::SortedDistances(test::AreaSamples(theirs, kSamples), test::SurfaceDistance(ours));
  EXPECT_LE(test::Quantile(accuracy, 0.5), c.max_median * h);
  EXPECT_LE(test::Quantile(accuracy, 0.95), c.max_p95 * h);
  EXPECT_LE(test::Quantile(completeness, 0.5), c.max_median * h);
  EXPECT_LE(test::Quantile(completeness, 0.95), c.max_p95 * h);
  ::testing::Test::RecordProperty("accuracy_median_h", std::to_string(test::Quantile(accuracy, 0.5) / h));
  ::testing::Test::RecordProperty("accuracy_p95_h", std::to_string(test::Quantile(accuracy, 0.95) / h));
  ::testing::Test::RecordProperty("completeness_median_h",
                                  std::to_string(test::Quantile(completeness, 0.5) / h));
  ::testing::Test::RecordProperty("completeness_p95_h",
                                  std::to_string(test::Quantile(completeness, 0.95) / h));
}

// Clean samples of a CAD part with sharp edges, convex and concave (issue 38
// item 3: accuracy p95 at most 1 sp, the median nearest-neighbour distance,
// about 0.49 h here). With the creases kept (reconstruct/crease.h) the p95
// is 0.1 h (0.21 sp measured with 20 000 samples); rounded off it was 1.2 h.
TEST(ReconstructSharedData, BrokenBulletWithOutwardNormalsMatchesTruth) {
  CheckAgainstTruth({"broken_bullet_50k.xyz", "broken_bullet_gt.obj", {}, 0.3, 0.49});
}

// A simulated scan with uneven density and noise of about the point spacing
// (median 0.45 h from the truth, p95 1.7 h).
TEST(ReconstructSharedData, AbcScanWithoutNormalsMatchesTruth) {
  CheckAgainstTruth({"abc_00016513_scan.xyz", "abc_00016513_gt.ply", {}, 0.4, 2.5});
}

}  // namespace
}  // namespace meshseg
