#include "reconstruct/crease.h"

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

struct Neighbourhood {
  std::vector<Eigen::Vector3d> at, normal;
  std::vector<double> weight;
};

// Points on a grid of spacing 0.05 within 0.25 of `centre` on two half
// planes that meet along the y axis: face 0 runs from it along e0 = −x, face 1
// along e1 = (−cos φ, 0, −sin φ), φ the dihedral angle. Convex: the solid is
// the wedge between them; else its complement. Inward normals, the Gaussian
// weights of the projection (project_to_points.h), Gaussian noise of
// `noise` along each face's normal.
Neighbourhood Wedge(const Eigen::Vector3d& centre, double dihedral_deg, bool convex, double noise) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  const double radius = 0.25, phi = dihedral_deg * M_PI / 180.0;
  const Eigen::Vector3d e[2] = {{-1, 0, 0}, {-std::cos(phi), 0, -std::sin(phi)}};
  Eigen::Vector3d inward[2] = {(e[1] - e[1].dot(e[0]) * e[0]).normalized(),
                               (e[0] - e[0].dot(e[1]) * e[1]).normalized()};
  Neighbourhood out;
  for (int face = 0; face < 2; ++face) {
    const Eigen::Vector3d n = convex ? inward[face] : -inward[face];
    for (double u = face == 0 ? 0.0 : 0.05; u <= 0.5; u += 0.05) {
      for (double y = -0.5; y <= 0.5; y += 0.05) {
        const Eigen::Vector3d p = u * e[face] + Eigen::Vector3d(0, y, 0) + noise * g(rng) * n;
        if ((p - centre).norm() > radius) continue;
        out.at.push_back(p);
        out.normal.push_back(n);
        out.weight.push_back(std::exp(-4.0 * (p - centre).squaredNorm() / (radius * radius)));
      }
    }
  }
  return out;
}

TEST(FitCrease, FindsTheTwoPlanesOfARightAngledEdge) {
  const Neighbourhood n = Wedge({-0.05, 0, 0}, 90.0, true, 0.0);
  const auto crease = FitCrease(n.at, n.normal, n.weight);
  ASSERT_TRUE(crease.has_value());
  EXPECT_TRUE(crease->convex);
  EXPECT_NEAR(std::abs(crease->normal[0].dot(crease->normal[1])), 0.0, 1e-9);
  // The line is the y axis; the corner cut off a rounded edge is restored.
  const Eigen::Vector3d on = crease->OntoLine({-0.03, 0.1, -0.03});
  EXPECT_NEAR(on.x(), 0.0, 1e-9);
  EXPECT_NEAR(on.z(), 0.0, 1e-9);
  EXPECT_NEAR(on.y(), 0.1, 1e-9);
  const Eigen::Vector3d inside_corner(-0.02, 0.0,
                                      -0.05);  // inside, nearer face x = 0
  EXPECT_NEAR((crease->Nearest(inside_corner) - Eigen::Vector3d(0, 0, -0.05)).norm(), 0.0, 1e-9);
  // Outside the edge, beyond both faces: the nearest surface point is the edge.
  EXPECT_NEAR((crease->Nearest({0.05, 0.0, 0.04}) - Eigen::Vector3d(0, 0, 0)).norm(), 0.0, 1e-9);
}

TEST(FitCrease, AConcaveEdgeIsTheUnionOfTheHalfSpaces) {
  const Neighbourhood n = Wedge({-0.05, 0, 0}, 90.0, false, 0.0);
  const auto crease = FitCrease(n.at, n.normal, n.weight);
  ASSERT_TRUE(crease.has_value());
  EXPECT_FALSE(crease->convex);
  // Above face 0, in the solid, nearer face 0 than face 1: onto face 0, not
  // onto its plane's continuation or the edge.
  const Eigen::Vector3d p(-0.08, 0.0, 0.02);
  EXPECT_NEAR((crease->Nearest(p) - Eigen::Vector3d(-0.08, 0, 0)).norm(), 0.0, 1e-9);
}

TEST(FitCrease, ASideSplitsThePointsAtTheBisector) {
  const Neighbourhood n = Wedge({0, 0, 0}, 90.0, true, 0.0);
  const auto crease = FitCrease(n.at, n.normal, n.weight);
  ASSERT_TRUE(crease.has_value());
  const int face0 = crease->Side({-0.2, 0, 0});
  const int face1 = crease->Side({0, 0, -0.2});
  EXPECT_NE(face0, face1);
  EXPECT_EQ(crease->Side({-0.1, 0.05, -0.01}), face0);
  EXPECT_EQ(crease->Side({-0.01, 0.05, -0.1}), face1);
}

TEST(FitCrease, ShallowEdgesAndNoisyPlanesAreOnePlane) {
  // Normals 20° apart (a dihedral of 160°): below kMinCreaseAngleDeg.
  const Neighbourhood shallow = Wedge({-0.05, 0, 0}, 160.0, true, 0.0);
  EXPECT_FALSE(FitCrease(shallow.at, shallow.normal, shallow.weight).has_value());
  // One noisy plane (σ 0.01) whose normals scatter by 30°: its rms about one
  // plane is the noise, no misfit for two planes to explain.
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  Neighbourhood plane;
  for (double x = -0.25; x <= 0.25; x += 0.05) {
    for (double y = -0.25; y <= 0.25; y += 0.05) {
      plane.at.emplace_back(x, y, 0.01 * g(rng));
      plane.normal.push_back(Eigen::Vector3d(0.3 * g(rng), 0.3 * g(rng), 1.0).normalized());
      plane.weight.push_back(std::exp(-4.0 * (x * x + y * y) / 0.0625));
    }
  }
  EXPECT_FALSE(FitCrease(plane.at, plane.normal, plane.weight, 0.01).has_value());
}

TEST(FitCrease, ANoisyRightAngleIsStillACrease) {
  const Neighbourhood n = Wedge({-0.05, 0, 0}, 90.0, true, 0.005);
  const auto crease = FitCrease(n.at, n.normal, n.weight, 0.005);
  ASSERT_TRUE(crease.has_value());
  EXPECT_NEAR(std::abs(crease->normal[0].dot(crease->normal[1])), 0.0, 0.1);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
