#include "segment/absorb_leftovers.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Sheet;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 4.0;

double Deg(double d) { return d * kPi / 180.0; }

// 60 degrees of a round of radius 4 about the z axis, 15 long: u the
// angle, v the height.
void BuildRound(Sheet* s) {
  BuildSheet(
      [](double u, double v) {
        const Eigen::Vector3d e(std::cos(u), std::sin(u), 0.0);
        return std::make_pair(Eigen::Vector3d(kRadius * e + v * Eigen::Vector3d::UnitZ()), e);
      },
      Deg(-30.0), Deg(30.0), 31, 0.0, 15.0, 31, /*distance=*/0.1, /*angle_deg=*/5.0, s);
}

// rounded_prism at 0.15 h, seed 77: a round merged from pieces came out of
// the merge with a nearly flat cylinder (r 469) fitted to part of it, took
// 25 leftovers without a refit and kept that surface to the end, so the
// boundary refinement let its faces take 14 % of it.
TEST(AbsorbLeftoversTest, RegionsThatGrowAreRefitted) {
  Sheet s;
  BuildRound(&s);
  // Leftovers: the first 9 degrees; region 0: the next 40, with a stale,
  // nearly flat surface; region 1: the last 11, with its own (off) surface.
  // The leftovers touch region 0 only.
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const double deg = s.u[v] * 180.0 / kPi;
    labels[v] = deg < -21.0 ? -1 : deg <= 19.0 ? 0 : 1;
  }
  std::vector<RegionState> regions(2);
  regions[0].type = regions[1].type = SurfaceType::kCylinder;
  regions[0].surface =
      Cylinder{Eigen::Vector3d(kRadius - 469.0, 0.0, 0.0), Eigen::Vector3d::UnitZ(), 469.0};
  const Cylinder off{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 4.5};
  regions[1].surface = off;
  RebuildVertexLists(labels, &regions);
  const std::size_t size_1 = regions[1].vertices.size();

  ASSERT_TRUE(AbsorbLeftovers(s.c, &labels, &regions).ok());
  for (const int l : labels) EXPECT_GE(l, 0);
  // Region 0 took leftovers and fits them: its surface is the round.
  EXPECT_NEAR(std::get<Cylinder>(regions[0].surface).radius, kRadius, 1e-6);
  // Region 1 took none and keeps what it had.
  EXPECT_EQ(regions[1].vertices.size(), size_1);
  EXPECT_EQ(std::get<Cylinder>(regions[1].surface).radius, off.radius);
}

}  // namespace
}  // namespace meshseg::segment_internal
