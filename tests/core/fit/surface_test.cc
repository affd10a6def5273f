#include "meshseg/surface.h"

#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace meshseg {
namespace {

TEST(Surface, TypeOfAndName) {
  EXPECT_EQ(TypeOf(Plane{}), SurfaceType::kPlane);
  EXPECT_EQ(TypeOf(Cylinder{}), SurfaceType::kCylinder);
  EXPECT_EQ(TypeOf(Cone{}), SurfaceType::kCone);
  EXPECT_EQ(TypeOf(Sphere{}), SurfaceType::kSphere);
  EXPECT_EQ(TypeOf(Torus{}), SurfaceType::kTorus);
  EXPECT_EQ(TypeOf(Quadric{}), SurfaceType::kQuadric);
  EXPECT_EQ(std::string(SurfaceTypeName(SurfaceType::kCone)), "cone");
  EXPECT_EQ(std::string(SurfaceTypeName(SurfaceType::kFreeform)), "freeform");
}

TEST(Surface, AxisOfTheSurfacesOfRevolution) {
  const Eigen::Vector3d p(1, 2, 3);
  const std::optional<AxisLine> cylinder = AxisOf(Cylinder{p, Eigen::Vector3d(0, 0, 2), 1.0});
  ASSERT_TRUE(cylinder.has_value());
  EXPECT_EQ(cylinder->point, p);
  EXPECT_EQ(cylinder->direction, Eigen::Vector3d::UnitZ());  // made unit
  EXPECT_EQ(AxisOf(Cone{p, Eigen::Vector3d::UnitX(), 0.3})->point, p);
  EXPECT_EQ(AxisOf(Torus{p, Eigen::Vector3d(0, 3, 0), 2.0, 0.5})->direction,
            Eigen::Vector3d::UnitY());
  EXPECT_FALSE(AxisOf(Plane{}).has_value());
  EXPECT_FALSE(AxisOf(Sphere{}).has_value());
  EXPECT_FALSE(AxisOf(Quadric{}).has_value());
}

}  // namespace
}  // namespace meshseg
