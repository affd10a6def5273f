// SplitOffPlanes on sheets: a boss top absorbed by its cone (a crease),
// also with noise, and a fillet that took rows of its floor (a tangent
// junction).
#include "segment/split_off_planes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "segment/decide_type.h"
#include "segment/energy.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::RegionsFromLabels;
using testing::Sheet;

constexpr double kSigma = 0.01;
constexpr int kTopRows = 17;   // the top: radius 1 to 5
constexpr int kConeRows = 34;  // the cone: 8.5 down its side

void BuildBoss(Sheet* s) { testing::BuildBoss(kTopRows, kConeRows, kSigma, s); }

TEST(SplitOffPlanesTest, TopAbsorbedByItsConeIsSplitOff) {
  Sheet s;
  BuildBoss(&s);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});

  EXPECT_EQ(SplitOffPlanes(s.c, &labels, &regions).value(), std::vector<int>{0});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
  EXPECT_EQ(regions[1].type, SurfaceType::kPlane);
  // Every top vertex but the rim's goes to the plane, every cone vertex
  // below the rim stays.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] < kTopRows - 1.5) {
      EXPECT_EQ(labels[v], 1) << "top row " << s.u[v];
    } else if (s.u[v] > kTopRows - 0.5) {
      EXPECT_EQ(labels[v], 0) << "cone row " << s.u[v];
    }
  }
}

TEST(SplitOffPlanesTest, LeavesNoVertexAloneAmongTheOtherSide) {
  // The top and the cone in one region typed sphere, with noise (test_piece
  // at 0.15 h, seed 56): where the sphere fitted to the cone rows passes
  // close to the plane, the noise puts single vertices nearer to the other
  // surface than to their own (6 here, without the hole filling).
  Sheet s;
  BuildBoss(&s);
  std::mt19937 random(1);
  std::normal_distribution<double> noise(0.0, kSigma);
  for (std::size_t v = 0; v < s.u.size(); ++v) {
    s.c.graph.positions[v] += noise(random) * s.field.normal[v];
  }
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kSphere});

  EXPECT_EQ(SplitOffPlanes(s.c, &labels, &regions).value(), std::vector<int>{0});
  ASSERT_EQ(regions.size(), 2u);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const auto around = s.c.graph.Neighbors(static_cast<int>(v));
    EXPECT_FALSE(
        std::all_of(around.begin(), around.end(), [&](int u) { return labels[u] != labels[v]; }))
        << "row " << s.u[v] << " column " << s.v[v];
  }
}

TEST(SplitOffPlanesTest, TopWithARoundedRimIsSplitOff) {
  // The top and the cone in one region typed cone, with noise, the top's
  // rim row 1.5 sigma low, as marching cubes rounds a crease: a plane
  // through the top misses it 0.25 to 0.5 sigma beyond the noise (test_piece
  // at 0.15 h, seeds 261 and 385: 0.41 and 0.36).
  Sheet s;
  BuildBoss(&s);
  std::mt19937 random(1);
  std::normal_distribution<double> noise(0.0, kSigma);
  std::vector<int> top;
  for (std::size_t v = 0; v < s.u.size(); ++v) {
    s.c.graph.positions[v] += noise(random) * s.field.normal[v];
    if (s.u[v] > kTopRows - 1.5 && s.u[v] < kTopRows - 0.5) {
      s.c.graph.positions[v].z() -= 1.5 * kSigma;
    }
    if (s.u[v] < kTopRows - 0.5) top.push_back(static_cast<int>(v));
  }
  const double top_error = ModelError(s.c, FitType(s.c, SurfaceType::kPlane, top));
  ASSERT_GT(top_error, kMinModelError * kSigma);
  ASSERT_LT(top_error, kScoredNearError * kSigma);
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});

  EXPECT_EQ(SplitOffPlanes(s.c, &labels, &regions).value(), std::vector<int>{0});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[1].type, SurfaceType::kPlane);
  const auto on_plane =
      std::count_if(top.begin(), top.end(), [&](int v) { return labels[v] == 1; });
  EXPECT_GE(on_plane, 0.9 * static_cast<double>(top.size()));
}

TEST(SplitOffPlanesTest, NothingSplitsAtNoiseZero) {
  Sheet s;
  BuildBoss(&s);
  s.c.noise_sigma = 0.0;
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCone});
  EXPECT_TRUE(SplitOffPlanes(s.c, &labels, &regions).value().empty());
  EXPECT_EQ(regions.size(), 1u);
}

TEST(SplitOffPlanesTest, FloorRowsAFilletTookAreSplitOffWithoutACrease) {
  // A quarter-round fillet of radius 1 (rows 0.1 apart) grown 6 rows into
  // the floor it runs tangent into: its cylinder misses those rows, and
  // they meet the fillet without a crease. E prices the boundary between
  // them at a smooth edge's full cost, and still falls: the floor rows go
  // to a plane, the fillet's rows stay on the cylinder.
  Sheet s;
  constexpr double kRowStep = 0.1;
  constexpr int kFloorRows = 6, kFilletRows = 16;
  BuildSheet(
      [](double row, double v) {
        if (row < kFloorRows) {
          return std::pair{Eigen::Vector3d(kRowStep * (row - kFloorRows), v, 0.0),
                           Eigen::Vector3d(Eigen::Vector3d::UnitZ())};
        }
        const double t = (row - kFloorRows) * std::numbers::pi / 2.0 / kFilletRows;
        return std::pair{Eigen::Vector3d(std::sin(t), v, 1.0 - std::cos(t)),
                         Eigen::Vector3d(-std::sin(t), 0.0, std::cos(t))};
      },
      0.0, kFloorRows + kFilletRows, kFloorRows + kFilletRows + 1, 0.0, 3.0, 31,
      /*distance=*/5.0 * kSigma, /*angle_deg=*/10.0, &s);
  s.c.noise_sigma = kSigma;
  std::vector<int> labels(s.u.size(), 0);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kCylinder});
  const double before = TotalEnergy(s.c, labels, regions);
  EXPECT_EQ(SplitOffPlanes(s.c, &labels, &regions).value(), std::vector<int>{0});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_LT(TotalEnergy(s.c, labels, regions), before);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[1].type, SurfaceType::kPlane);
  // One row either side of the tangent line may go either way (the two
  // surfaces meet there within the noise).
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] < kFloorRows - 1.5) {
      EXPECT_EQ(labels[v], 1) << "floor row " << s.u[v];
    } else if (s.u[v] > kFloorRows + 1.5) {
      EXPECT_EQ(labels[v], 0) << "fillet row " << s.u[v];
    }
  }
}

}  // namespace
}  // namespace meshseg::segment_internal
