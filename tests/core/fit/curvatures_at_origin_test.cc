#include <cmath>

#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

// Sign convention: κ < 0 where the surface bends away from the normal
// (a sphere seen with its outward normal has κ = -1/R).
constexpr double kRelTol = 0.02;  // curvature error of a quadratic fit over a cap of radius R/5

TEST(CurvaturesAtOrigin, SphereWithOutwardNormal) {
  const Sphere sp{Eigen::Vector3d(1, 2, 3), 5.0};
  const Eigen::Vector3d pole = test::Tilt().col(2);
  const test::Samples s = test::SampleSphere(sp, pole, 0.2, 6, 12, 0.0);
  const Eigen::Vector3d origin = sp.center + sp.radius * pole;
  const HeightFunction h = FitHeightFunction(s.points, origin, pole);
  ASSERT_TRUE(h.valid);
  const PrincipalCurvatures pc = CurvaturesAtOrigin(h);
  EXPECT_NEAR(pc.kappa_max, -0.2, kRelTol * 0.2);
  EXPECT_NEAR(pc.kappa_min, -0.2, kRelTol * 0.2);
  EXPECT_LT((pc.normal - pole).norm(), 1e-6);
}

TEST(CurvaturesAtOrigin, SphereWithTiltedFrameUsesSlopeTerms) {
  // The frame normal is 25 deg off the surface normal, so a3, a4 != 0.
  const Sphere sp{Eigen::Vector3d::Zero(), 5.0};
  const test::Samples s = test::SampleSphere(sp, Eigen::Vector3d::UnitZ(), 0.2, 6, 12, 0.0);
  const Eigen::Vector3d frame_normal(std::sin(0.44), 0.0, std::cos(0.44));
  const HeightFunction h = FitHeightFunction(s.points, Eigen::Vector3d(0, 0, 5), frame_normal);
  ASSERT_TRUE(h.valid);
  EXPECT_GT(std::hypot(h.a[3], h.a[4]), 0.4);
  const PrincipalCurvatures pc = CurvaturesAtOrigin(h);
  EXPECT_NEAR(pc.kappa_max, -0.2, kRelTol * 0.2);
  EXPECT_NEAR(pc.kappa_min, -0.2, kRelTol * 0.2);
  // The tilted graph has cubic terms the quadratic cannot hold: 0.6 deg.
  EXPECT_LT((pc.normal - Eigen::Vector3d::UnitZ()).norm(), 1e-2);
}

TEST(CurvaturesAtOrigin, CylinderDirections) {
  const Cylinder c{Eigen::Vector3d::Zero(), test::Tilt().col(0), 2.0};
  const test::Samples s = test::SampleCylinder(c, 0.5, 0.8, 8, 8, 0.0);
  // Origin: the middle sample; normal: its exact normal.
  const std::size_t mid = s.points.size() / 2;
  const HeightFunction h = FitHeightFunction(s.points, s.points[mid], s.normals[mid]);
  ASSERT_TRUE(h.valid);
  const PrincipalCurvatures pc = CurvaturesAtOrigin(h);
  EXPECT_NEAR(pc.kappa_max, -0.5, kRelTol * 0.5);
  EXPECT_NEAR(pc.kappa_min, 0.0, kRelTol * 0.5);
  EXPECT_GT(std::abs(pc.dir_min.dot(c.axis_direction)), 1.0 - 1e-4);
  EXPECT_LT(std::abs(pc.dir_max.dot(c.axis_direction)), 1e-2);
  EXPECT_NEAR(pc.dir_max.dot(pc.normal), 0.0, 1e-9);
}

TEST(CurvaturesAtOrigin, ExactQuadraticWithSlope) {
  // h = 0.5 u² + 0.2 u: X_u = (1, 0, 0.2), κ_u = 1 / (1 + 0.04)^(3/2), κ_w = 0.
  HeightFunction h;
  h.a = {0.5, 0.0, 0.0, 0.2, 0.0, 0.0};
  const PrincipalCurvatures pc = CurvaturesAtOrigin(h);
  EXPECT_NEAR(pc.kappa_max, 1.0 / std::pow(1.04, 1.5), 1e-12);
  EXPECT_NEAR(pc.kappa_min, 0.0, 1e-12);
  EXPECT_LT((pc.dir_max - Eigen::Vector3d(1, 0, 0.2).normalized()).norm(), 1e-9);
}

}  // namespace
}  // namespace meshseg
