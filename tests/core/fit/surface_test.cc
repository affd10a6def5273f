#include "meshseg/surface.h"

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

}  // namespace
}  // namespace meshseg
