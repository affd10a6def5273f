#include "generate/marching_cubes.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::generate_internal {
namespace {

constexpr double kH = 0.5;

Grid GridAround(double half_width) {
  Grid g;
  g.h = kH;
  g.origin = Eigen::Vector3d::Constant(-half_width - 2.0 * kH) + kH * Eigen::Vector3d(0.3, 0.1, 0.7);
  g.nx = g.ny = g.nz = static_cast<int>(std::ceil(2.0 * (half_width + 2.0 * kH) / kH)) + 2;
  return g;
}

TEST(MarchingCubes, SphereIsClosedOnTheSurfaceAndFacesOut) {
  Csg solid;
  const Eigen::Vector3d c(0.2, -0.1, 0.3);
  solid.SetRoot(solid.AddLeaf(MakeLeaf(Sphere{c, 5.0}, 0)));
  const auto raw = MarchingCubes(solid, GridAround(5.5), {});
  ASSERT_TRUE(raw.ok()) << raw.status();
  const int nv = static_cast<int>(raw->vertices.size());
  const int nf = static_cast<int>(raw->triangles.size());
  EXPECT_EQ(2 * nv - nf, 4);  // genus 0, if closed
  for (const Eigen::Vector3d& v : raw->vertices) EXPECT_NEAR((v - c).norm(), 5.0, 1e-9 * kH);
  for (const auto& t : raw->triangles) {
    const Eigen::Vector3d n = (raw->vertices[t[1]] - raw->vertices[t[0]])
                                  .cross(raw->vertices[t[2]] - raw->vertices[t[0]]);
    EXPECT_GT(n.dot(raw->vertices[t[0]] - c), 0.0);
    EXPECT_GT(n.norm(), 0.0);
  }
}

// The box's vertices lie on its faces; no two vertices coincide, because
// each stays kMinEdgeFraction of an edge away from grid points.
TEST(MarchingCubes, BoxVerticesLieOnFacesAndAreDistinct) {
  Csg solid;
  std::vector<int> faces;
  for (int a = 0; a < 3; ++a) {
    for (double s : {-1.0, 1.0}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[a] = s;
      faces.push_back(solid.AddLeaf(MakeLeaf(Plane{3.0 * n, n}, 2 * a + (s > 0))));
    }
  }
  solid.SetRoot(solid.Intersection(faces));
  const auto raw = MarchingCubes(solid, GridAround(3.0), {});
  ASSERT_TRUE(raw.ok()) << raw.status();
  for (size_t v = 0; v < raw->vertices.size(); ++v) {
    EXPECT_NEAR(raw->vertices[v].cwiseAbs().maxCoeff(), 3.0, 1e-9);
  }
  for (const auto& t : raw->triangles) {
    const double area = (raw->vertices[t[1]] - raw->vertices[t[0]])
                            .cross(raw->vertices[t[2]] - raw->vertices[t[0]]).norm();
    EXPECT_GT(area, 1e-6 * kH * kH);
  }
}

TEST(MarchingCubes, EmptyGridRegionGivesNoTriangles) {
  Csg solid;
  solid.SetRoot(solid.AddLeaf(MakeLeaf(Sphere{Eigen::Vector3d(100, 0, 0), 1.0}, 0)));
  const auto raw = MarchingCubes(solid, GridAround(3.0), {});
  ASSERT_TRUE(raw.ok());
  EXPECT_TRUE(raw->triangles.empty());
}

}  // namespace
}  // namespace meshseg::generate_internal
