// SnapFillets on a sheet: plate_boss's boss in profile, its top (z = 20,
// radius 4 out to 8), an edge round of radius 2 turning down to its side
// (the cylinder of radius 10), and 4 of the side, with a noise of 0.01.
#include "segment/snap_fillets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <vector>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::RegionsFromLabels;
using testing::Sheet;

constexpr double kSigma = 0.01;
constexpr double kTop = 4.0;                            // profile length of the top
constexpr double kRound = 2.0;                          // the round's radius
constexpr double kArc = kRound * std::numbers::pi / 2;  // profile length of the round
constexpr double kSide = 4.0;
constexpr double kLength = kTop + kArc + kSide;
constexpr int kRows = 56;
constexpr int kAround = 64;

// Profile length s from the top's inner rim: its point and normal in
// (rho, z).
std::pair<Eigen::Vector2d, Eigen::Vector2d> Profile(double s) {
  if (s < kTop) return {Eigen::Vector2d(4.0 + s, 20.0), Eigen::Vector2d(0.0, 1.0)};
  if (s < kTop + kArc) {
    const double t = (s - kTop) / kRound;
    const Eigen::Vector2d n(std::sin(t), std::cos(t));
    return {Eigen::Vector2d(8.0, 18.0) + kRound * n, n};
  }
  return {Eigen::Vector2d(10.0, 18.0 - (s - kTop - kArc)), Eigen::Vector2d(1.0, 0.0)};
}

// A deterministic offset of about kSigma along the normal (uniform, so
// sqrt(3) kSigma at most).
double Noise(double s, double phi) {
  const double x = std::sin(s * 127.1 + phi * 311.7) * 43758.5453;
  return (2.0 * (x - std::floor(x)) - 1.0) * std::sqrt(3.0) * kSigma;
}

// The boss profile swept around the z axis; the sheet's u is s.
void BuildBoss(Sheet* s) {
  BuildSheet(
      [](double u, double phi) {
        const auto [p, n] = Profile(u);
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d normal = n.x() * radial + n.y() * Eigen::Vector3d::UnitZ();
        const Eigen::Vector3d point = p.x() * radial + p.y() * Eigen::Vector3d::UnitZ();
        return std::pair{Eigen::Vector3d(point + Noise(u, phi) * normal), normal};
      },
      0.0, kLength, kRows, 0.0, 2.0 * std::numbers::pi * (kAround - 1) / kAround, kAround,
      /*distance=*/5.0 * kSigma, /*angle_deg=*/10.0, s);
  s->c.noise_sigma = kSigma;
}

// Where a vertex truly is: 0 the top, 1 the round, 2 the side; -1 within
// `margin` of a tangent line, where the fillet and the face beside it
// stay within the noise of each other.
int TrueFace(double s, double margin) {
  if (s < kTop - margin) return 0;
  if (s > kTop + margin && s < kTop + kArc - margin) return 1;
  if (s > kTop + kArc + margin) return 2;
  return -1;
}

// Labels by profile length: 0 before cuts[0], 1 up to cuts[1], and so on.
std::vector<int> LabelsCutAt(const Sheet& s, std::initializer_list<double> cuts) {
  std::vector<int> labels(s.u.size(), 0);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    for (const double cut : cuts) labels[v] += s.u[v] >= cut ? 1 : 0;
  }
  return labels;
}

// The round's region as it grows at 0.15 h: 1.5 of the top and of the side
// beside it.
constexpr double kTaken = 1.5;

TEST(FilletTorusTest, TouchesThePlaneAndTheCylinder) {
  const Plane top{.point = Eigen::Vector3d(0, 0, 20), .normal = Eigen::Vector3d::UnitZ()};
  const Cylinder side{.axis_origin = Eigen::Vector3d(1, 2, 5),
                      .axis_direction = -Eigen::Vector3d::UnitZ(),
                      .radius = 10.0};
  const Torus convex = FilletTorus(top, side, 2.0, -1, -1);
  EXPECT_NEAR((convex.center - Eigen::Vector3d(1, 2, 18)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(convex.axis_direction.z(), 1.0, 1e-12);  // oriented like the plane's normal
  EXPECT_DOUBLE_EQ(convex.major_radius, 8.0);
  EXPECT_DOUBLE_EQ(convex.minor_radius, 2.0);
  // It touches the top at radius 8 and the side at height 18.
  EXPECT_NEAR(SignedDistance(convex, Eigen::Vector3d(9, 2, 20)), 0.0, 1e-12);
  EXPECT_NEAR(SignedDistance(convex, Eigen::Vector3d(11, 2, 18)), 0.0, 1e-12);
  // A concave fillet outside the cylinder, above the plane.
  const Torus concave = FilletTorus(top, side, 3.0, 1, 1);
  EXPECT_DOUBLE_EQ(concave.major_radius, 13.0);
  EXPECT_NEAR(SignedDistance(concave, Eigen::Vector3d(11, 2, 23)), 0.0, 1e-12);
  EXPECT_NEAR(SignedDistance(concave, Eigen::Vector3d(14, 2, 20)), 0.0, 1e-12);
}

TEST(SnapFilletsTest, RoundBentIntoTopAndSideGivesTheirRowsBack) {
  Sheet s;
  BuildBoss(&s);
  std::vector<int> labels = LabelsCutAt(s, {kTop - kTaken, kTop + kArc + kTaken});
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus, SurfaceType::kCylinder});
  // The torus fitted to that region bends through the top and the side.
  const Torus& bent = std::get<Torus>(regions[1].surface);
  ASSERT_GT(std::abs(bent.minor_radius - kRound), 0.1);

  EXPECT_EQ(SnapFillets(s.c, &labels, &regions), std::vector<int>{1});
  ASSERT_EQ(regions.size(), 3u);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const int face = TrueFace(s.u[v], 0.5);
    if (face >= 0) {
      EXPECT_EQ(labels[v], face) << "s " << s.u[v];
    }
  }
  // Refitted on the round alone: the round.
  ASSERT_EQ(regions[1].type, SurfaceType::kTorus);
  const Torus& round = std::get<Torus>(regions[1].surface);
  EXPECT_NEAR(round.major_radius, 8.0, 0.02);
  EXPECT_NEAR(round.minor_radius, kRound, 0.02);
}

TEST(SnapFilletsTest, TopTheRoundGrewOverBecomesAPlane) {
  // No region holds the top: the round's region has all of it.
  Sheet s;
  BuildBoss(&s);
  std::vector<int> labels = LabelsCutAt(s, {kTop + kArc + kTaken});
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kTorus, SurfaceType::kCylinder});

  EXPECT_EQ(SnapFillets(s.c, &labels, &regions), std::vector<int>{0});
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_EQ(regions[2].type, SurfaceType::kPlane);
  const int where[] = {2, 0, 1};  // top, round, side
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const int face = TrueFace(s.u[v], 0.5);
    if (face >= 0) {
      EXPECT_EQ(labels[v], where[face]) << "s " << s.u[v];
    }
  }
  const Plane& top = std::get<Plane>(regions[2].surface);
  EXPECT_NEAR(std::abs(top.normal.z()), 1.0, 1e-4);
  EXPECT_NEAR(top.point.z(), 20.0, 0.01);
  const Torus& round = std::get<Torus>(regions[0].surface);
  EXPECT_NEAR(round.minor_radius, kRound, 0.02);
}

TEST(SnapFilletsTest, RoundThatFitsItsInteriorIsLeftAlone) {
  Sheet s;
  BuildBoss(&s);
  std::vector<int> labels = LabelsCutAt(s, {kTop, kTop + kArc});
  const std::vector<int> before = labels;
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus, SurfaceType::kCylinder});
  const Torus own = std::get<Torus>(regions[1].surface);
  EXPECT_TRUE(SnapFillets(s.c, &labels, &regions).empty());
  EXPECT_EQ(labels, before);
  EXPECT_EQ(std::get<Torus>(regions[1].surface).minor_radius, own.minor_radius);
}

TEST(SnapFilletsTest, TorusOnAChamferIsNoFillet) {
  // A 45-degree chamfer from the top down to the side, typed torus: no
  // fillet between the two meets it, and nothing changes.
  Sheet s;
  BuildSheet(
      [](double u, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        Eigen::Vector2d p, n;
        if (u < 4.0) {
          p = {4.0 + u, 20.0}, n = {0.0, 1.0};
        } else if (u < 4.0 + 2.0 * std::numbers::sqrt2) {
          const double t = (u - 4.0) / std::numbers::sqrt2;
          p = {8.0 + t, 20.0 - t}, n = Eigen::Vector2d(1.0, 1.0).normalized();
        } else {
          p = {10.0, 18.0 - (u - 4.0 - 2.0 * std::numbers::sqrt2)}, n = {1.0, 0.0};
        }
        const Eigen::Vector3d normal = n.x() * radial + n.y() * z;
        return std::pair{Eigen::Vector3d(p.x() * radial + p.y() * z + Noise(u, phi) * normal),
                         normal};
      },
      0.0, 4.0 + 2.0 * std::numbers::sqrt2 + 4.0, kRows, 0.0,
      2.0 * std::numbers::pi * (kAround - 1) / kAround, kAround, 5.0 * kSigma, 10.0, &s);
  s.c.noise_sigma = kSigma;
  std::vector<int> labels = LabelsCutAt(s, {3.0, 4.0 + 2.0 * std::numbers::sqrt2 + 1.0});
  const std::vector<int> before = labels;
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus, SurfaceType::kCylinder});
  EXPECT_TRUE(SnapFillets(s.c, &labels, &regions).empty());
  EXPECT_EQ(labels, before);
}

}  // namespace
}  // namespace meshseg::segment_internal
