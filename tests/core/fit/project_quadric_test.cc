#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "meshseg/fit.h"

namespace meshseg {
namespace {

// x²/a² + y²/b² + z²/c² - 1 = 0, scaled so |∇f| ~ 1 near the surface.
Quadric Ellipsoid(double a, double b, double c) {
  Quadric q;
  q.c = {1 / (a * a), 1 / (b * b), 1 / (c * c), 0, 0, 0, 0, 0, 0, -1};
  return q;
}

double F(const Quadric& q, const Eigen::Vector3d& x) {
  const auto& c = q.c;
  return c[0] * x.x() * x.x() + c[1] * x.y() * x.y() + c[2] * x.z() * x.z() + c[3] * x.x() * x.y() +
         c[4] * x.y() * x.z() + c[5] * x.z() * x.x() + c[6] * x.x() + c[7] * x.y() + c[8] * x.z() +
         c[9];
}

TEST(ProjectQuadric, SphereQuadricMatchesClosedForm) {
  // (x-1)² + y² + z² - 4 = 0.
  Quadric q;
  q.c = {1, 1, 1, 0, 0, 0, -2, 0, 0, 1 - 4};
  const Sphere sp{Eigen::Vector3d(1, 0, 0), 2.0};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    if ((p - sp.center).norm() < 0.5) continue;
    const Projection a = Project(q, p);
    const Projection b = Project(sp, p);
    EXPECT_LT((a.point - b.point).norm(), 1e-9) << p.transpose();
    EXPECT_NEAR(a.distance, b.distance, 1e-9);
    EXPECT_LT((a.normal - b.normal).norm(), 1e-9);
  }
}

// Points near an ellipsoid, started from the true normal of a nearby point
// (as a vertex normal would be): the 3-step foot point lies on the quadric
// and p - foot is along the surface normal.
TEST(ProjectQuadric, ConvergesOnEllipsoid) {
  const Quadric q = Ellipsoid(3.0, 2.0, 1.5);
  constexpr double kOnSurfaceTol = 1e-9;
  constexpr double kLateralTol = 1e-4;  // |(p - foot) x normal|; semi-axes 1.5 to 3
  constexpr double kDistanceTol = 1e-5;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double th = std::acos(2 * u(rng) - 1), ph = 2 * M_PI * u(rng);
    const Eigen::Vector3d on(3.0 * std::sin(th) * std::cos(ph), 2.0 * std::sin(th) * std::sin(ph),
                             1.5 * std::cos(th));
    const Eigen::Vector3d n =
        Eigen::Vector3d(on.x() / 9.0, on.y() / 4.0, on.z() / 2.25).normalized();
    const double offset = 0.2 * (u(rng) - 0.5);  // ± 0.1, a few edge lengths
    const Eigen::Vector3d p = on + offset * n;
    const Eigen::Vector3d hint =
        (n + 0.05 * Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)).normalized();
    const Projection pr = Project(q, p, hint);
    EXPECT_NEAR(F(q, pr.point), 0.0, kOnSurfaceTol);
    const Eigen::Vector3d d = p - pr.point;
    EXPECT_LT(d.cross(pr.normal).norm(), kLateralTol);
    EXPECT_NEAR(pr.distance, offset, kDistanceTol) << p.transpose();
  }
}

TEST(ProjectQuadric, NoRealRootFallsBackToGradientStep) {
  // The line through p along the hint misses the unit sphere.
  Quadric q;
  q.c = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
  const Projection pr = Project(q, Eigen::Vector3d(0, 0, 3), Eigen::Vector3d(1, 0, 0));
  ASSERT_TRUE(pr.point.allFinite() && std::isfinite(pr.distance));
  EXPECT_NEAR(pr.distance, 2.0, 1e-6);
}

TEST(ProjectQuadric, FlatGradientIsFinite) {
  Quadric q;  // all zero: f = 0 everywhere
  const Projection pr = Project(q, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(pr.point.allFinite() && pr.normal.allFinite() && std::isfinite(pr.distance));
  Quadric sphere;
  sphere.c = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
  const Projection c = Project(sphere, Eigen::Vector3d::Zero());
  EXPECT_TRUE(c.point.allFinite() && c.normal.allFinite() && std::isfinite(c.distance));
}

}  // namespace
}  // namespace meshseg
