#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/fit.h"
#include "samples.h"

namespace meshseg {
namespace {

constexpr double kTol = 1e-9;

std::vector<Eigen::Vector3d> QueryPoints() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  std::vector<Eigen::Vector3d> q;
  for (int i = 0; i < 200; ++i) q.emplace_back(u(rng), u(rng), u(rng));
  return q;
}

// p = foot + distance * normal, |normal| = 1, and the foot lies on the surface.
void ExpectConsistent(const Surface& s, const Eigen::Vector3d& p) {
  const Projection pr = Project(s, p);
  ASSERT_TRUE(pr.point.allFinite() && pr.normal.allFinite() && std::isfinite(pr.distance));
  EXPECT_NEAR(pr.normal.norm(), 1.0, kTol);
  EXPECT_LT((pr.point + pr.distance * pr.normal - p).norm(), kTol) << p.transpose();
  EXPECT_NEAR(SignedDistance(s, pr.point), 0.0, kTol) << p.transpose();
  EXPECT_NEAR(SignedDistance(s, p), pr.distance, kTol);
}

TEST(Project, PlaneFootNormalAndSign) {
  const Plane pl{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 2)};
  const Projection pr = Project(pl, Eigen::Vector3d(5, 5, 4.5));
  EXPECT_NEAR(pr.distance, 1.5, kTol);
  EXPECT_LT((pr.point - Eigen::Vector3d(5, 5, 3)).norm(), kTol);
  EXPECT_LT((pr.normal - Eigen::Vector3d::UnitZ()).norm(), kTol);
  for (const auto& p : QueryPoints()) ExpectConsistent(pl, p);
}

TEST(Project, SphereFootNormalAndSign) {
  const Sphere sp{Eigen::Vector3d(1, -1, 0.5), 2.0};
  EXPECT_NEAR(SignedDistance(sp, Eigen::Vector3d(1, -1, 3.5)), 1.0, kTol);
  EXPECT_NEAR(SignedDistance(sp, Eigen::Vector3d(1, -1, 1.5)), -1.0, kTol);
  for (const auto& p : QueryPoints()) ExpectConsistent(sp, p);
}

TEST(Project, SphereCentreIsFinite) {
  const Sphere sp{Eigen::Vector3d(1, -1, 0.5), 2.0};
  const Projection pr = Project(sp, sp.center);
  EXPECT_NEAR(pr.distance, -2.0, kTol);
  EXPECT_NEAR((pr.point - sp.center).norm(), 2.0, kTol);
}

TEST(Project, CylinderFootNormalAndSign) {
  const Cylinder c{Eigen::Vector3d(0.5, 0, 0), test::Tilt() * Eigen::Vector3d::UnitZ(), 1.5};
  const Eigen::Vector3d e = c.axis_direction.unitOrthogonal();
  const Projection pr = Project(c, c.axis_origin + 3.0 * c.axis_direction + 2.0 * e);
  EXPECT_NEAR(pr.distance, 0.5, kTol);
  EXPECT_LT((pr.normal - e).norm(), kTol);
  for (const auto& p : QueryPoints()) ExpectConsistent(c, p);
}

TEST(Project, CylinderAxisPointIsFinite) {
  const Cylinder c{Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitZ(), 1.5};
  const Projection pr = Project(c, Eigen::Vector3d(0.5, 0, 7));
  EXPECT_NEAR(pr.distance, -1.5, kTol);
  EXPECT_NEAR(SignedDistance(c, pr.point), 0.0, kTol);
}

TEST(Project, ConeFootNormalAndSign) {
  const Cone c{Eigen::Vector3d(0, 0, -2), test::Tilt() * Eigen::Vector3d::UnitZ(), 0.4};
  // Points in front of the apex.
  for (const auto& q : QueryPoints()) {
    if ((q - c.apex).dot(c.axis_direction) > 0.0) ExpectConsistent(c, q);
  }
  // A point at distance 1 outside the generator through apex + axis + r e.
  const Eigen::Vector3d e = c.axis_direction.unitOrthogonal();
  const Eigen::Vector3d on = c.apex + 3.0 * (std::sin(0.4) * e + std::cos(0.4) * c.axis_direction);
  const Eigen::Vector3d n = std::cos(0.4) * e - std::sin(0.4) * c.axis_direction;
  EXPECT_NEAR(SignedDistance(c, on + 0.7 * n), 0.7, kTol);
  EXPECT_NEAR(SignedDistance(c, on - 0.7 * n), -0.7, kTol);
}

TEST(Project, ConeApexAndAxisAreFinite) {
  const Cone c{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::UnitZ(), 0.5};
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(0, 0, -2)}) {
    const Projection pr = Project(c, p);
    EXPECT_TRUE(pr.point.allFinite() && pr.normal.allFinite() && std::isfinite(pr.distance));
  }
  EXPECT_NEAR(SignedDistance(c, Eigen::Vector3d(0, 0, 2)), -2.0 * std::sin(0.5), kTol);
  // Behind the apex the apex is closest.
  EXPECT_NEAR(std::abs(SignedDistance(c, Eigen::Vector3d(0, 0, -2))), 2.0, kTol);
  EXPECT_LT(Project(c, Eigen::Vector3d(0, 0, -2)).point.norm(), kTol);
}

TEST(Project, TorusFootNormalAndSign) {
  const Torus t{Eigen::Vector3d(0.2, 0.1, 0), test::Tilt() * Eigen::Vector3d::UnitZ(), 2.0, 0.5};
  const Eigen::Vector3d e = t.axis_direction.unitOrthogonal();
  EXPECT_NEAR(SignedDistance(t, t.center + 3.0 * e), 0.5, kTol);
  EXPECT_NEAR(SignedDistance(t, t.center + 2.0 * e), -0.5, kTol);
  for (const auto& p : QueryPoints()) ExpectConsistent(t, p);
}

TEST(Project, TorusAxisPointIsFinite) {
  const Torus t{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 2.0, 0.5};
  const Projection pr = Project(t, Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(pr.distance, std::sqrt(5.0) - 0.5, kTol);
  EXPECT_NEAR(SignedDistance(t, pr.point), 0.0, kTol);
}

// SignedDistance (and SurfaceDistance, made once per surface) leaves out
// the foot point and normal but must give
// Project's distance to the bit (the segmentation's energy sums it, and a
// rounding would move its decisions): random points with random hints, and
// the special points (on an axis, at a centre, behind an apex), for every
// type, the quadric included.
TEST(Project, SignedDistanceIsProjectsDistanceBitForBit) {
  const Eigen::Vector3d axis = test::Tilt() * Eigen::Vector3d::UnitZ();
  Quadric quadric;  // x^2 + y^2 / 4 - z - 1
  quadric.c = {1.0, 0.25, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, -1.0};
  const std::vector<Surface> surfaces = {
      Plane{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.3, -0.2, 2)},
      Sphere{Eigen::Vector3d(1, -1, 0.5), 2.0},
      Cylinder{Eigen::Vector3d(0.5, 0, 0), axis, 1.5},
      Cone{Eigen::Vector3d(0, 0, -2), axis, 0.4},
      Torus{Eigen::Vector3d(0.2, 0.1, 0), axis, 2.0, 0.5},
      quadric};
  std::vector<Eigen::Vector3d> points = QueryPoints();
  points.push_back(Eigen::Vector3d(0.5, 0, 0) + 2.0 * axis);   // the cylinder's axis
  points.push_back(Eigen::Vector3d(0, 0, -2) - 1.0 * axis);    // behind the apex
  points.push_back(Eigen::Vector3d(0, 0, -2));                 // the apex
  points.push_back(Eigen::Vector3d(0.2, 0.1, 0) + 0.7 * axis);  // the torus' axis
  points.push_back(Eigen::Vector3d(1, -1, 0.5));                // the sphere's centre
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  for (const Surface& s : surfaces) {
    const SurfaceDistance distance_to(s);  // made once, used for every point
    for (const Eigen::Vector3d& p : points) {
      for (const Eigen::Vector3d& hint :
           {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(g(rng), g(rng), g(rng))}) {
        const double fast = SignedDistance(s, p, hint);
        const double kept = distance_to(p, hint);
        const double full = Project(s, p, hint).distance;
        EXPECT_EQ(std::memcmp(&fast, &full, sizeof fast), 0)
            << "type " << s.index() << " at " << p.transpose() << ": " << fast << " vs " << full;
        EXPECT_EQ(std::memcmp(&kept, &full, sizeof kept), 0)
            << "type " << s.index() << " at " << p.transpose() << ": " << kept << " vs " << full;
      }
    }
  }
}

}  // namespace
}  // namespace meshseg
