#include "topology/surface_intersection.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::topology_internal {
namespace {

constexpr double kTol = 1e-9;
const IntersectionTolerances kLoose{8.0 * std::numbers::pi / 180.0, 0.1};
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

std::vector<Eigen::Vector3d> CirclePoints(const Eigen::Vector3d& c, double r) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 8; ++i) {
    const double t = i * std::numbers::pi / 4;
    out.push_back(c + r * Eigen::Vector3d(std::cos(t), std::sin(t), 0.0));
  }
  return out;
}

TEST(IntersectSurfaces, PlaneAndSphereMeetInACircle) {
  const auto g = IntersectSurfaces(Plane{kZ, kZ}, Sphere{Eigen::Vector3d::Zero(), 2.0},
                                   CirclePoints(kZ, std::sqrt(3.0)), kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->type, CurveGeometryType::kCircle);
  EXPECT_TRUE(g->analytic);
  EXPECT_NEAR(g->radius, std::sqrt(3.0), kTol);
  EXPECT_NEAR((g->point - kZ).norm(), 0.0, kTol);
}

TEST(IntersectSurfaces, PlaneCutsTorusInTheCircleNearTheCurve) {
  const Torus torus{Eigen::Vector3d::Zero(), kZ, 10.0, 2.0};
  const Plane plane{Eigen::Vector3d::Zero(), kZ};
  auto g = IntersectSurfaces(plane, torus, CirclePoints(Eigen::Vector3d::Zero(), 8.1), kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->radius, 8.0, kTol);
  g = IntersectSurfaces(plane, torus, CirclePoints(Eigen::Vector3d::Zero(), 11.9), kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->radius, 12.0, kTol);
}

TEST(IntersectSurfaces, CoaxialCylinderAndConeMeetInACircle) {
  // Cone opening upwards from the origin at 45 degrees; cylinder radius 3.
  const Cone cone{Eigen::Vector3d::Zero(), kZ, std::numbers::pi / 4};
  const Cylinder cylinder{Eigen::Vector3d(0, 0, -5), -kZ, 3.0};
  const auto g = IntersectSurfaces(cone, cylinder, CirclePoints(3.0 * kZ, 3.0), kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->type, CurveGeometryType::kCircle);
  EXPECT_NEAR(g->radius, 3.0, kTol);
  EXPECT_NEAR(g->point.z(), 3.0, kTol);
}

TEST(IntersectSurfaces, PlaneTiltedWithinToleranceIsMeasuredOnTheAxis) {
  // A plane through (0, 0, 1) tilted by 2 degrees, its reference point 50
  // away from the axis; the circle must sit at z = 1 on the axis.
  const double tilt = 2.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d n(std::sin(tilt), 0.0, std::cos(tilt));
  const Eigen::Vector3d far = kZ + 50.0 * n.cross(Eigen::Vector3d::UnitY()).normalized();
  const auto g = IntersectSurfaces(Plane{far, n}, Cylinder{Eigen::Vector3d::Zero(), kZ, 2.0},
                                   CirclePoints(kZ, 2.0), kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->point.z(), 1.0, kTol);
}

TEST(IntersectSurfaces, TwoPlanesMeetInALine) {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}};
  const auto g = IntersectSurfaces(Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()},
                                   Plane{Eigen::Vector3d::Zero(), kZ}, points, kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->type, CurveGeometryType::kLine);
  EXPECT_NEAR(std::abs(g->direction.y()), 1.0, kTol);
  EXPECT_NEAR(g->point.x(), 0.0, kTol);
  EXPECT_NEAR(g->point.z(), 0.0, kTol);
}

TEST(IntersectSurfaces, FilletCylinderTouchesItsPlaneAlongALine) {
  // Cylinder of radius 1 along y at height 1 resting on z = 0.
  const std::vector<Eigen::Vector3d> points = {{0.02, 0, 0}, {0.0, 3, 0}};
  const auto g = IntersectSurfaces(Plane{Eigen::Vector3d::Zero(), kZ},
                                   Cylinder{kZ, Eigen::Vector3d::UnitY(), 1.0}, points, kLoose);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->type, CurveGeometryType::kLine);
  EXPECT_NEAR(g->point.x(), 0.0, kTol);
  EXPECT_NEAR(g->point.z(), 0.0, kTol);
}

TEST(IntersectSurfaces, ObliquePlaneAndCylinderHaveNoClosedForm) {
  const Eigen::Vector3d n = Eigen::Vector3d(1, 0, 1).normalized();
  EXPECT_FALSE(IntersectSurfaces(Plane{Eigen::Vector3d::Zero(), n},
                                 Cylinder{Eigen::Vector3d::Zero(), kZ, 1.0},
                                 CirclePoints(Eigen::Vector3d::Zero(), 1.0), kLoose)
                   .has_value());
}

}  // namespace
}  // namespace meshseg::topology_internal
