// The data term's unit (energy.h, "Data unit"): th_dis / k on a mesh as
// read; on a mesh reconstructed from noisy points (SegmentParams::
// point_noise) the vertices' own scatter, never coarser than th_dis / k. A
// vertex's cost scales with the unit, its cap stays at th_dis, and the
// boundary and label costs stay as they are.
#include <Eigen/Core>
#include <string>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/segment.h"
#include "segment/energy.h"
#include "segment/estimate_noise.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildFlatSide;
using testing::Sheet;

// th_dis 0.3, set by the resolution (0.5 l_avg); the vertices' own scatter
// 0.01: the unit th_dis / k is 0.1.
SegmentEstimates ResolutionLimited() {
  SegmentEstimates e;
  e.mean_edge_length = 0.6;
  e.noise_sigma = 0.01;
  e.distance_tolerance = 0.3;
  return e;
}

TEST(DataUnitScale, OneOnAMeshAsRead) {
  EXPECT_EQ(DataUnitScale(ResolutionLimited(), std::nullopt), 1.0);
}

TEST(DataUnitScale, TheVerticesScatterOnAReconstructionFromNoisyPoints) {
  // Points of noise 0.08 averaged by the projection to a scatter of 0.01:
  // unit 0.01, ten times finer than th_dis / k, so a residual costs 100
  // times as much. The points' noise says only that the vertices are
  // estimates from noisy points.
  EXPECT_NEAR(DataUnitScale(ResolutionLimited(), 0.08), 100.0, 1e-9);
  EXPECT_NEAR(DataUnitScale(ResolutionLimited(), 0.001), 100.0, 1e-9);
  // Never coarser than th_dis / k: a scatter at or above it keeps the unit.
  SegmentEstimates noisy = ResolutionLimited();
  noisy.noise_sigma = 0.1;
  EXPECT_EQ(DataUnitScale(noisy, 0.3), 1.0);
  noisy.noise_sigma = 0.2;
  EXPECT_EQ(DataUnitScale(noisy, 0.3), 1.0);
  // Noise-free points: only the resolution's error is left, the unit as read.
  EXPECT_EQ(DataUnitScale(ResolutionLimited(), 0.0), 1.0);
  // No scatter measured: the unit as read.
  SegmentEstimates exact = ResolutionLimited();
  exact.noise_sigma = 0.0;
  EXPECT_EQ(DataUnitScale(exact, 0.08), 1.0);
}

TEST(DataUnit, ScalesTheResidualCostButNotWhereItsCapIs) {
  Sheet s;
  BuildFlatSide(&s);  // th_dis 0.225, unit 0.075
  const int v = 0;
  const auto off = [](double d) {
    return Surface{Plane{.point = Eigen::Vector3d(0, d, 0), .normal = Eigen::Vector3d::UnitY()}};
  };
  const double near = VertexCost(s.c, v, off(0.05));
  const double far = VertexCost(s.c, v, off(1.0));  // beyond th_dis: an outlier
  const double outlier = OutlierCost(s.c, v);
  EXPECT_LT(near, outlier);
  EXPECT_DOUBLE_EQ(far, outlier);
  s.c.unit_scale = 9.0;  // unit 0.025
  EXPECT_DOUBLE_EQ(VertexCost(s.c, v, off(0.05)), 9.0 * near);
  EXPECT_DOUBLE_EQ(OutlierCost(s.c, v), 9.0 * outlier);
  EXPECT_DOUBLE_EQ(VertexCost(s.c, v, off(1.0)), OutlierCost(s.c, v));
  // A vertex 0.2 off, within th_dis, is still no outlier.
  EXPECT_LT(VertexCost(s.c, v, off(0.2)), OutlierCost(s.c, v));
}

TEST(PointNoise, BelowZeroIsRefused) {
  absl::StatusOr<GeneratedPart> part = GeneratePart("small_block", {.seed = 7});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<CurvatureField> field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  SegmentParams params;
  params.point_noise = -0.1;
  const absl::StatusOr<Segmentation> seg = Segment(part->mesh, *field, params);
  EXPECT_EQ(seg.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(seg.status().message().find("point_noise"), std::string::npos);
}

}  // namespace
}  // namespace meshseg::segment_internal
