#include "generate/csg.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace meshseg::generate_internal {
namespace {

using V = Eigen::Vector3d;

TEST(LeafValue, IsTheSignedDistanceNegativeInside) {
  EXPECT_DOUBLE_EQ(LeafValue(MakeLeaf(Plane{V(0, 0, 1), V(0, 0, 2)}, 0), V(5, 5, 3)), 2.0);
  EXPECT_DOUBLE_EQ(LeafValue(MakeLeaf(Cylinder{V(0, 0, 0), V(0, 0, 1), 2.0}, 0), V(3, 4, 9)), 3.0);
  EXPECT_DOUBLE_EQ(LeafValue(MakeLeaf(Sphere{V(1, 0, 0), 2.0}, 0), V(1, 0, 1)), -1.0);
  EXPECT_NEAR(LeafValue(MakeLeaf(Torus{V(0, 0, 0), V(0, 0, 1), 5.0, 1.0}, 0), V(5, 0, 0.5)), -0.5,
              1e-15);
  const Leaf cone = MakeLeaf(Cone{V(0, 0, 0), V(0, 0, 1), std::numbers::pi / 4}, 0);
  EXPECT_NEAR(LeafValue(cone, V(1, 0, 1)), 0.0, 1e-15);
  EXPECT_NEAR(LeafValue(cone, V(0, 0, 1)), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(LeafValue(cone, V(0, 0, -2)), 2.0, 1e-15);  // behind the apex
}

TEST(Csg, UnionIntersectionDifferenceReportTheActiveLeaf) {
  Csg csg;
  const int big = csg.AddLeaf(MakeLeaf(Sphere{V(0, 0, 0), 2.0}, 0));
  const int small = csg.AddLeaf(MakeLeaf(Sphere{V(0, 0, 0), 1.0}, 1));
  csg.SetRoot(csg.Difference(big, small));
  EXPECT_EQ(csg.Eval(V(0, 0, 0.5)).leaf, 1);
  EXPECT_NEAR(csg.Eval(V(0, 0, 0.5)).f, 0.5, 1e-15);
  EXPECT_EQ(csg.Eval(V(0, 0, 1.8)).leaf, 0);
  EXPECT_LT(csg.Eval(V(0, 0, 1.5)).f, 0.0);
  const int u = csg.Union({small, csg.AddLeaf(MakeLeaf(Sphere{V(3, 0, 0), 1.0}, 2))});
  csg.SetRoot(u);
  EXPECT_EQ(csg.Eval(V(2.5, 0, 0)).leaf, 2);
  EXPECT_LT(csg.Eval(V(2.5, 0, 0)).f, 0.0);
}

}  // namespace
}  // namespace meshseg::generate_internal
