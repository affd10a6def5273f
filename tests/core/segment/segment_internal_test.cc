// The shared pieces of the segment stage: FitType's per-type fit over a
// region's vertices.
#include "segment/segment_internal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

namespace meshseg::segment_internal {
namespace {

// A context over bare points and normals: FitType reads positions, n'_i and
// vertex areas only.
struct PointContext {
  CurvatureField field;
  SegmentContext c;

  void Add(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    c.graph.positions.push_back(p);
    field.normal.push_back(n);
    field.smooth_normal.push_back(n);
    c.vertex_area.push_back(1.0);
  }
  void Finish() {
    c.graph.offsets.assign(c.graph.positions.size() + 1, 0);
    c.curvature = &field;
  }
  std::vector<int> All() const {
    std::vector<int> v(c.graph.positions.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>(i);
    return v;
  }
};

// Points of the torus (axis z through the origin) at tube angles [t0, t1]
// and all the way around the axis.
PointContext TorusBand(double major, double minor, double t0, double t1) {
  PointContext pc;
  constexpr int kRings = 12, kAround = 48;
  for (int i = 0; i <= kRings; ++i) {
    const double t = t0 + (t1 - t0) * i / kRings;
    for (int j = 0; j < kAround; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / kAround;
      const Eigen::Vector3d n(std::cos(t) * std::cos(phi), std::cos(t) * std::sin(phi),
                              std::sin(t));
      const Eigen::Vector3d p =
          Eigen::Vector3d(major * std::cos(phi), major * std::sin(phi), 0.0) + minor * n;
      pc.Add(p, n);
    }
  }
  pc.Finish();
  return pc;
}

TEST(FitTypeTest, RingTorusBandIsATorus) {
  // A fillet-like band: R 8, r 2, the upper outer quarter of the tube.
  PointContext pc = TorusBand(8.0, 2.0, 0.0, std::numbers::pi / 2.0);
  const FitResult fit = FitType(pc.c, SurfaceType::kTorus, pc.All());
  ASSERT_TRUE(fit.ok());
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_NEAR(t.major_radius, 8.0, 1e-3);
  EXPECT_NEAR(t.minor_radius, 2.0, 1e-3);
}

TEST(FitTypeTest, FlatDiscWithTheStartOfARoundIsNoTorus) {
  // plate_boss's boss top as a region grown 1.5 rows into its edge round:
  // a disc of radius 6 and the first 25 degrees of a round of radius 2.
  // A torus fits it only as a spindle torus (R 6.5, r 88 on the noisy part)
  // whose cusp sits on the disc's centre.
  constexpr double kDisc = 6.0, kRound = 2.0;
  PointContext pc;
  for (double rho = 0.0; rho < kDisc; rho += 0.25) {
    const int around = std::max(1, static_cast<int>(2.0 * std::numbers::pi * rho / 0.25));
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / around;
      pc.Add(Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), 0.0),
             Eigen::Vector3d::UnitZ());
    }
  }
  for (double deg = 5.0; deg <= 25.0; deg += 5.0) {
    const double t = deg * std::numbers::pi / 180.0;
    const int around = static_cast<int>(2.0 * std::numbers::pi * kDisc / 0.25);
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / around;
      const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
      const Eigen::Vector3d n = std::sin(t) * radial + std::cos(t) * Eigen::Vector3d::UnitZ();
      pc.Add(kDisc * radial - kRound * Eigen::Vector3d::UnitZ() + kRound * n, n);
    }
  }
  pc.Finish();
  const FitResult fit = FitType(pc.c, SurfaceType::kTorus, pc.All());
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_FALSE(fit.ok()) << "fitted R " << t.major_radius << " r " << t.minor_radius;
}

TEST(FitTypeTest, SpindleTorusAwayFromItsAxisIsATorus) {
  // The outer sheet of the same spindle torus around its equator (a barrel):
  // every point is more than r - R from the axis.
  PointContext pc = TorusBand(2.0, 10.0, -0.5, 0.5);
  const FitResult fit = FitType(pc.c, SurfaceType::kTorus, pc.All());
  ASSERT_TRUE(fit.ok());
  const auto& t = std::get<Torus>(fit.surface);
  EXPECT_NEAR(t.major_radius, 2.0, 1e-3);
  EXPECT_NEAR(t.minor_radius, 10.0, 1e-3);
}

}  // namespace
}  // namespace meshseg::segment_internal
