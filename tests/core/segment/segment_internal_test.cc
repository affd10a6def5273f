// The shared pieces of the segment stage: FitType's per-type fit over a
// region's vertices, and the piece of a vertex set that holds a seed.
#include "segment/segment_internal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>
#include <variant>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::AllVertices;
using testing::BuildSheet;
using testing::Sheet;
using testing::TorusPoint;

// Points of the torus (axis z through the origin) at tube angles [t0, t1]
// and all the way around the axis.
void TorusBand(double major, double minor, double t0, double t1, Sheet* s) {
  constexpr int kRings = 13, kAround = 48;
  BuildSheet(TorusPoint(major, minor), t0, t1, kRings, 0.0,
             2.0 * std::numbers::pi * (kAround - 1) / kAround, kAround, /*distance=*/0.1,
             /*angle_deg=*/5.0, s);
}

TEST(FitTypeTest, RingTorusBandIsATorus) {
  // A fillet-like band: R 8, r 2, the upper outer quarter of the tube.
  Sheet s;
  TorusBand(8.0, 2.0, 0.0, std::numbers::pi / 2.0, &s);
  const FitResult fit = FitType(s.c, SurfaceType::kTorus, AllVertices(s));
  ASSERT_TRUE(fit.ok());
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_NEAR(t.major_radius, 8.0, 1e-3);
  EXPECT_NEAR(t.minor_radius, 2.0, 1e-3);
}

TEST(FitTypeTest, FlatDiscWithTheStartOfARoundIsNoTorus) {
  // plate_boss's boss top as a region grown 1.5 rows into its edge round
  // (testing::BuildDiscWithRoundStart). A torus fits it only as a spindle
  // torus (R 6.5, r 88 on the noisy part) whose cusp sits on the disc's
  // centre.
  Sheet s;
  testing::BuildDiscWithRoundStart(/*distance=*/0.15, &s);
  const FitResult fit = FitType(s.c, SurfaceType::kTorus, AllVertices(s));
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_FALSE(fit.ok()) << "fitted R " << t.major_radius << " r " << t.minor_radius;
}

TEST(FitTypeTest, SpindleTorusAwayFromItsAxisIsATorus) {
  // The outer sheet of the same spindle torus around its equator (a barrel):
  // every point is more than r - R from the axis.
  Sheet s;
  TorusBand(2.0, 10.0, -0.5, 0.5, &s);
  const FitResult fit = FitType(s.c, SurfaceType::kTorus, AllVertices(s));
  ASSERT_TRUE(fit.ok());
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_NEAR(t.major_radius, 2.0, 1e-3);
  EXPECT_NEAR(t.minor_radius, 10.0, 1e-3);
}

// A flat strip of 20 columns by 5 rows, 1 apart in the plane z = 0.
void BuildStrip(Sheet* s) {
  BuildSheet(
      [](double u, double v) {
        return std::pair{Eigen::Vector3d(u, v, 0.0), Eigen::Vector3d::UnitZ()};
      },
      0.0, 19.0, 20, 0.0, 4.0, 5, /*distance=*/0.1, /*angle_deg=*/5.0, s);
}

// The vertices of the strip whose column is not in `gap`.
std::vector<int> StripWithout(const Sheet& s, int gap_from, int gap_to) {
  std::vector<int> out;
  for (int v = 0; v < static_cast<int>(s.u.size()); ++v) {
    const int column = static_cast<int>(std::lround(s.u[v]));
    if (column < gap_from || column > gap_to) out.push_back(v);
  }
  return out;
}

TEST(PieceHoldingSeedTest, KeepsTheSeedsSideOfAWideGap) {
  Sheet s;
  BuildStrip(&s);
  // Columns 7-10 missing (4 columns, wider than kPieceBridge): two pieces;
  // the seed, in columns 12-14, is on the right one.
  const std::vector<int> set = StripWithout(s, 7, 10);
  std::vector<int> seed;
  for (const int v : set) {
    if (s.u[v] >= 12.0 && s.u[v] <= 14.0) seed.push_back(v);
  }
  const std::vector<int> piece = PieceHoldingSeed(s.c, set, seed);
  EXPECT_EQ(piece.size(), 9u * 5u);
  for (const int v : piece) EXPECT_GE(s.u[v], 11.0);
  // A gap of kPieceBridge columns (noise) does not cut it.
  const std::vector<int> holed = StripWithout(s, 8, 7 + kPieceBridge);
  EXPECT_EQ(PieceHoldingSeed(s.c, holed, seed).size(), holed.size());
}

TEST(PieceHoldingSeedTest, TheSeedJoinsTheVerticesAroundIt) {
  Sheet s;
  BuildStrip(&s);
  // The set: columns 0-3 (20 vertices) and columns 9 and 15 (10), which lie
  // 5 columns apart; the seed, columns 10-14, is not in the set.
  std::vector<int> set;
  std::vector<int> seed;
  for (int v = 0; v < static_cast<int>(s.u.size()); ++v) {
    const long column = std::lround(s.u[v]);
    if (column <= 3 || column == 9 || column == 15) set.push_back(v);
    if (column >= 10 && column <= 14) seed.push_back(v);
  }
  const std::vector<int> piece = PieceHoldingSeed(s.c, set, seed);
  ASSERT_EQ(piece.size(), 10u);
  for (const int v : piece) EXPECT_GE(s.u[v], 9.0);
  // None of the set at the seed: no piece holds it.
  const std::vector<int> far = StripWithout(s, 4, 19);
  EXPECT_TRUE(PieceHoldingSeed(s.c, far, seed).empty());
}

}  // namespace
}  // namespace meshseg::segment_internal
