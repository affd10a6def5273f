#include "remesh/small_features.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "cad_shapes.h"

namespace meshseg::remesh_internal {
namespace {

using testing::MeshOf;

TEST(SmallRadiusEdges, FindsTheEdgesBetweenTheStripsOfASmallCylinder) {
  // 24 strips of r = 3: the edge between two strips bends by 15 degrees over
  // a strip's width, r sin(7.5°) / 7.5° = 0.99715 r.
  const Mesh mesh = MeshOf(testing::CadCylinder(3.0, 10.0, 24));
  const std::vector<CurvedEdge> edges = SmallRadiusEdges(mesh.tri, 4.0, 30.0);
  // Not the strips' diagonals (flat), not the rims (90 degrees, a crease).
  ASSERT_EQ(edges.size(), 24u);
  for (const CurvedEdge& e : edges) {
    EXPECT_NEAR(e.radius, 3.0 * std::sin(std::numbers::pi / 24) / (std::numbers::pi / 24), 1e-9);
    EXPECT_NEAR((e.b - e.a).norm(), 10.0, 1e-9);  // along the axis
  }
}

TEST(SmallRadiusEdges, KeepsOnlyRadiiUnderTheLimit) {
  const Mesh mesh = MeshOf(testing::CadCylinder(3.0, 10.0, 24));
  EXPECT_TRUE(SmallRadiusEdges(mesh.tri, 2.9, 30.0).empty());
  // A 15-degree bend is a crease under a 10-degree feature angle.
  EXPECT_TRUE(SmallRadiusEdges(mesh.tri, 4.0, 10.0).empty());
}

TEST(SmallRadiusEdges, AFlatPlateWithAHoleHasOnlyTheHole) {
  const Mesh mesh = MeshOf(testing::CadPlateWithHole(20.0, 6.0, 2.5, 24));
  const std::vector<CurvedEdge> edges = SmallRadiusEdges(mesh.tri, 100.0, 30.0);
  ASSERT_EQ(edges.size(), 24u);
  for (const CurvedEdge& e : edges) {
    EXPECT_NEAR(std::hypot(e.a.x(), e.a.y()), 2.5, 1e-9);
    EXPECT_NEAR(e.radius, 2.5, 0.01 * 2.5);
  }
}

}  // namespace
}  // namespace meshseg::remesh_internal
