#include "topology/snap_corner.h"

#include <vector>

#include <gtest/gtest.h>

#include "meshseg/fit.h"

namespace meshseg::topology_internal {
namespace {

TEST(SnapCorner, ThreePlanesMeetInTheirCommonPoint) {
  const Surface x = Plane{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::UnitX()};
  const Surface y = Plane{Eigen::Vector3d(0, 2, 0), -Eigen::Vector3d::UnitY()};
  const Surface z = Plane{Eigen::Vector3d(0, 0, 3), Eigen::Vector3d(0.1, 0, 1).normalized()};
  const std::vector<const Surface*> surfaces = {&x, &y, &z};
  const auto p = SnapCorner(Eigen::Vector3d(1.2, 1.8, 3.1), surfaces, 1.0);
  ASSERT_TRUE(p.has_value());
  for (const Surface* s : surfaces) EXPECT_NEAR(SignedDistance(*s, *p), 0.0, 1e-9);
}

TEST(SnapCorner, PlaneCylinderAndPlaneMeetInAPoint) {
  const Surface side = Cylinder{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 2.0};
  const Surface top = Plane{Eigen::Vector3d(0, 0, 5), Eigen::Vector3d::UnitZ()};
  const Surface cut = Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()};
  const std::vector<const Surface*> surfaces = {&side, &top, &cut};
  const auto p = SnapCorner(Eigen::Vector3d(1.9, 0.1, 4.9), surfaces, 1.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR((*p - Eigen::Vector3d(2, 0, 5)).norm(), 0.0, 1e-9);
}

TEST(SnapCorner, TangentSurfacesAreNotSnapped) {
  // A fillet cylinder tangent to both planes: normals span only 2D.
  const Surface a = Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  const Surface b = Cylinder{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitY(), 1.0};
  const Surface c = Plane{Eigen::Vector3d(0, 0, 5), Eigen::Vector3d::UnitY()};
  const std::vector<const Surface*> surfaces = {&a, &b, &c};
  EXPECT_FALSE(SnapCorner(Eigen::Vector3d(0.05, 5.0, 0.0), surfaces, 1.0).has_value());
}

TEST(SnapCorner, FarPointAndTwoSurfacesAreNotSnapped) {
  const Surface x = Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  const Surface y = Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()};
  const Surface z = Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  const std::vector<const Surface*> three = {&x, &y, &z};
  EXPECT_FALSE(SnapCorner(Eigen::Vector3d(5, 5, 5), three, 1.0).has_value());
  const std::vector<const Surface*> two = {&x, &y};
  EXPECT_FALSE(SnapCorner(Eigen::Vector3d(0.1, 0.1, 0.1), two, 1.0).has_value());
}

}  // namespace
}  // namespace meshseg::topology_internal
