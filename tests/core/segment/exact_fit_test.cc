// The exact fit and the evidence test of the exact-facet path
// (segment/exact_fit.h) on a band of an exactly tessellated cylinder: the
// fit finds the cylinder through the corners to rounding, and fails when
// one corner is off it by more than tau; a group holds evidence for a
// curved type only with facets of three distinct normals and the type's
// parameters plus three corners.
#include "segment/exact_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <variant>
#include <vector>

#include "meshseg/mesh.h"
#include "segment/facet_mesh.h"
#include "cylinder_band.h"

namespace meshseg::segment_internal {
namespace {

constexpr int kAround = testing::kBandAround;
constexpr double kRadius = testing::kBandRadius;

// The band of cylinder_band.h, corner 0 pushed `push` outward.
Mesh Band(double push) { return testing::CylinderBand(push); }

std::vector<int> FirstFacets(int count) {
  std::vector<int> facets;
  for (int f = 0; f < count; ++f) facets.push_back(f);
  return facets;
}

TEST(FitExactly, TheBandsCornersGiveItsCylinder) {
  const Mesh mesh = Band(0.0);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  ASSERT_EQ(fm.facet_count(), 2 * kAround);
  const double tau = 1e-12 * fm.diagonal;
  const std::optional<Surface> fit =
      FitExactly(fm, SurfaceType::kCylinder, FirstFacets(2 * kAround), tau);
  ASSERT_TRUE(fit.has_value());
  const auto* cylinder = std::get_if<Cylinder>(&*fit);
  ASSERT_NE(cylinder, nullptr);
  EXPECT_NEAR(cylinder->radius, kRadius, 1e-9);
  EXPECT_NEAR(std::abs(cylinder->axis_direction.z()), 1.0, 1e-9);
  // The facet mesh is centred on its bounding box, which the axis crosses.
  const Eigen::Vector3d to_axis =
      cylinder->axis_origin - cylinder->axis_origin.dot(cylinder->axis_direction) *
                                  cylinder->axis_direction;
  EXPECT_NEAR(to_axis.norm(), 0.0, 1e-9);
  // No plane holds corners on a circle.
  EXPECT_FALSE(FitExactly(fm, SurfaceType::kPlane, FirstFacets(2 * kAround), tau).has_value());
}

// A corner 1e-3 off the cylinder (a billion tau): no cylinder passes within
// tau of every corner.
TEST(FitExactly, ACornerOffTheCylinderFitsNone) {
  const Mesh mesh = Band(1e-3);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  const double tau = 1e-12 * fm.diagonal;
  EXPECT_FALSE(
      FitExactly(fm, SurfaceType::kCylinder, FirstFacets(2 * kAround), tau).has_value());
  // The quads away from the pushed corner still fit it.
  std::vector<int> away;
  for (int f = 4; f < 2 * kAround - 4; ++f) away.push_back(f);
  EXPECT_TRUE(FitExactly(fm, SurfaceType::kCylinder, away, tau).has_value());
}

TEST(HoldsEvidence, ThreeDistinctNormalsAndEnoughCorners) {
  const Mesh mesh = Band(0.0);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  // One facet fixes only its own plane; two of one quad give a 4th corner.
  EXPECT_FALSE(HoldsEvidence(fm, SurfaceType::kPlane, FirstFacets(1)));
  EXPECT_TRUE(HoldsEvidence(fm, SurfaceType::kPlane, FirstFacets(2)));
  // Two quads: two normals, whatever the corners.
  EXPECT_FALSE(HoldsEvidence(fm, SurfaceType::kCylinder, FirstFacets(4)));
  // Three quads: three normals and 8 corners, a cylinder's 5 parameters + 3.
  EXPECT_TRUE(HoldsEvidence(fm, SurfaceType::kCylinder, FirstFacets(6)));
  // A cone's 6 + 3 need a fourth ruling.
  EXPECT_FALSE(HoldsEvidence(fm, SurfaceType::kCone, FirstFacets(6)));
  EXPECT_TRUE(HoldsEvidence(fm, SurfaceType::kCone, FirstFacets(8)));
}

}  // namespace
}  // namespace meshseg::segment_internal
