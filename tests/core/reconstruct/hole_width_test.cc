#include "reconstruct/hole_width.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

double MeanEdge(const std::vector<Eigen::Vector3d>& loop) {
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) length += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return length / static_cast<double>(loop.size());
}

// Sampled at a sixteenth of the mean edge: at most 2.24 / 16 < 0.15 mean
// edges above the true width (hole_width.h).
double Width(const std::vector<Eigen::Vector3d>& loop) {
  return HoleWidth(loop, MeanEdge(loop) / 16);
}

// 4 |A| / L, A the loop's vector area, L its length: the width measure
// HoleWidth replaces (a circle's diameter on a flat loop).
double VectorAreaWidth(const std::vector<Eigen::Vector3d>& loop) {
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d& a = loop[i];
    const Eigen::Vector3d& b = loop[(i + 1) % loop.size()];
    area += 0.5 * a.cross(b);
    length += (b - a).norm();
  }
  return 4.0 * area.norm() / length;
}

// A rim of radius 1 round the z axis running up and down by h (z = h cos 2θ):
// a hole's rim on a curved wall.
std::vector<Eigen::Vector3d> SaddleRim(double h, int n) {
  std::vector<Eigen::Vector3d> loop;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    loop.emplace_back(std::cos(t), std::sin(t), h * std::cos(2 * t));
  }
  return loop;
}

TEST(LeastAreaDisc, TriangulatesAConvexPolygonWithItsArea) {
  std::vector<Eigen::Vector3d> hexagon;
  for (int i = 0; i < 6; ++i) {
    const double t = 2 * M_PI * i / 6;
    hexagon.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  const auto triangles = LeastAreaDisc(hexagon);
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0.0;
  for (const auto& [a, b, c] : triangles) {
    area += 0.5 * (hexagon[b] - hexagon[a]).cross(hexagon[c] - hexagon[a]).norm();
  }
  EXPECT_NEAR(area, 1.5 * std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(LeastAreaDisc({hexagon[0], hexagon[1]}).empty());
}

// A skew quadrilateral has two triangulations of different area; the
// smaller is taken.
TEST(LeastAreaDisc, TakesTheSmallerDiagonalOfASkewQuadrilateral) {
  const std::vector<Eigen::Vector3d> quad = {{0, 0, 0}, {2, 0, 0}, {2, 1, 1.5}, {0, 1, 0}};
  const auto area = [&](int a, int b, int c) {
    return 0.5 * (quad[b] - quad[a]).cross(quad[c] - quad[a]).norm();
  };
  const double by_02 = area(0, 1, 2) + area(0, 2, 3), by_13 = area(0, 1, 3) + area(1, 2, 3);
  ASSERT_GT(std::abs(by_02 - by_13), 0.1);
  double taken = 0.0;
  for (const auto& [a, b, c] : LeastAreaDisc(quad)) taken += area(a, b, c);
  EXPECT_NEAR(taken, std::min(by_02, by_13), 1e-12);
}

// A flat round hole reads its diameter: the 64-gon's inscribed circle,
// 2 cos(π/64), and at most a seventh of an edge more (hole_width.h).
TEST(HoleWidth, IsTheDiameterOfAFlatRoundHole) {
  const std::vector<Eigen::Vector3d> circle = SaddleRim(0.0, 64);
  const double inscribed = 2 * std::cos(M_PI / 64);
  const double w = Width(circle);
  EXPECT_GE(w, inscribed);
  EXPECT_LE(w, inscribed + 0.15 * MeanEdge(circle));
  EXPECT_NEAR(VectorAreaWidth(circle), w, 0.15 * MeanEdge(circle));
}

// A flat round hole with a point at its centre: the largest ball centred on
// the disc that neither the rim nor the point enters lies half way between
// them: between cos(π/64) / 2 (towards an edge's middle) and 1 / 2 (the
// rim's circumcircle) in radius.
TEST(HoleWidth, KeepsClearOfThePointsItIsGiven) {
  const std::vector<Eigen::Vector3d> circle = SaddleRim(0.0, 64);
  const double step = MeanEdge(circle) / 16;
  const Clearance to_centre = [](const Eigen::Vector3d& q) { return q.norm(); };
  const double w = HoleWidth(circle, step, std::numeric_limits<double>::infinity(), to_centre);
  EXPECT_GE(w, std::cos(M_PI / 64));
  EXPECT_LE(w, 1.0 + 2.24 * step);
  // Points farther than the hole is wide change nothing.
  const Clearance far = [](const Eigen::Vector3d& q) { return (q - Eigen::Vector3d(0, 0, 5)).norm(); };
  EXPECT_DOUBLE_EQ(HoleWidth(circle, step, std::numeric_limits<double>::infinity(), far),
                   HoleWidth(circle, step));
}

// A slit 2 long, 0.02 wide, its long sides sampled at 0.04 like a mesh
// loop: it reads its gap (4 A / L reads about twice the gap).
TEST(HoleWidth, IsTheGapOfASlit) {
  std::vector<Eigen::Vector3d> slit;
  for (int i = 0; i <= 50; ++i) slit.emplace_back(0.04 * i, 0.0, 0.0);
  for (int i = 50; i >= 0; --i) slit.emplace_back(0.04 * i, 0.02, 0.0);
  const double w = Width(slit);
  EXPECT_GE(w, 0.02);
  EXPECT_LE(w, 0.02 + 0.15 * MeanEdge(slit));
  EXPECT_NEAR(VectorAreaWidth(slit), 2 * 0.02, 0.002);
}

// A round hole's rim running up and down a curved wall (z = h cos 2θ): any
// disc spanning it crosses the z axis it winds round, where every rim point
// is at least 1 away, so the hole is at least 2 wide, and no point of the
// saddle the rim bounds is further than sqrt(1 + h²) from it. 4 A / L reads
// it narrower: its vector area stays π while its length grows by a fifth.
TEST(HoleWidth, IsTheDiameterOfARoundHoleWhoseRimIsNotFlat) {
  const std::vector<Eigen::Vector3d> rim = SaddleRim(0.5, 96);
  const double w = Width(rim);
  EXPECT_GE(w, 2.0);
  EXPECT_LE(w, 2 * std::sqrt(1.0 + 0.25) + 0.15 * MeanEdge(rim));
  EXPECT_LT(VectorAreaWidth(rim), 0.85 * 2.0);
}

// A slit in a bent sheet (its two long sides along a quarter circle of
// radius 1, 0.05 apart along the bend's axis): it reads its gap.
TEST(HoleWidth, IsTheGapOfABentSlit) {
  constexpr double kGap = 0.05;
  std::vector<Eigen::Vector3d> slit;
  constexpr int kRows = 40;
  for (int i = 0; i <= kRows; ++i) {
    const double t = 0.5 * M_PI * i / kRows;
    slit.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  for (int i = kRows; i >= 0; --i) {
    const double t = 0.5 * M_PI * i / kRows;
    slit.emplace_back(std::cos(t), std::sin(t), kGap);
  }
  const double w = Width(slit);
  EXPECT_GE(w, kGap);
  EXPECT_LE(w, kGap + 0.15 * MeanEdge(slit));
}

TEST(HoleWidth, IsZeroBelowThreeVertices) {
  EXPECT_EQ(HoleWidth({}, 0.1), 0.0);
  EXPECT_EQ(HoleWidth({Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}, 0.1), 0.0);
}

// Stopped at 1 (the circle is 2 across), it returns a value above 1 without
// sampling the whole disc; stopped above its width, the full width.
TEST(HoleWidth, StopsOnceTheHoleIsWiderThanAsked) {
  const std::vector<Eigen::Vector3d> circle = SaddleRim(0.0, 64);
  const double step = MeanEdge(circle) / 16;
  const double stopped = HoleWidth(circle, step, 1.0);
  EXPECT_GT(stopped, 1.0);
  EXPECT_LT(stopped, 2.0);
  EXPECT_EQ(HoleWidth(circle, step, 3.0), HoleWidth(circle, step));
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
