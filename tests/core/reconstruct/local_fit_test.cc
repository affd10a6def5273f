#include "reconstruct/local_fit.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

TEST(B2, IsTheQuadraticBSplineOfEquation5) {
  EXPECT_DOUBLE_EQ(B2(0.0), 0.75);
  EXPECT_NEAR(B2(0.5 - 1e-12), B2(0.5), 1e-9);  // continuous at the knots
  EXPECT_DOUBLE_EQ(B2(0.5), 0.5);
  EXPECT_DOUBLE_EQ(B2(1.0), 0.125);
  EXPECT_DOUBLE_EQ(B2(1.5), 0.0);
  EXPECT_DOUBLE_EQ(B2(3.0), 0.0);
}

// A grid of points on the plane z = 0 with spacing 1 and inward normals −z:
// the solid is the half-space z < 0.
struct Plane {
  std::vector<Eigen::Vector3d> points, normals;
};

Plane NoisyPlane(double noise) {
  std::mt19937 rng(2);
  std::normal_distribution<double> g;
  Plane p;
  for (int x = -30; x <= 30; ++x) {
    for (int y = -30; y <= 30; ++y) {
      p.points.emplace_back(x, y, noise * g(rng));
      p.normals.emplace_back(0, 0, -1);
    }
  }
  return p;
}

TEST(FitSupport, GrowsOnAFlatPatchUntilTheToleranceAndFitsThePlane) {
  const Plane plane = NoisyPlane(0.2);
  const mesh_internal::PointIndex index(plane.points);
  const FitInput in{plane.points, plane.normals, index, /*epsilon=*/1.0, /*max_radius=*/100.0};
  const Support s = FitSupport(Eigen::Vector3d(0.3, -0.2, 0.5), 2.0, in);
  EXPECT_GT(s.radius, 4.0);  // the noise stays below ε, so the ball grows
  EXPECT_GT(s.point_count, 40);
  EXPECT_GT(s.m.dot(Eigen::Vector3d(0, 0, -1)), 0.999);
  EXPECT_NEAR(s.d.z(), 0.0, 0.1);
  EXPECT_NEAR(s.g(Eigen::Vector3d(0, 0, -2)), 2.0, 0.1);  // positive inside
  for (const auto& p : plane.points) {
    if ((p - s.center).norm() < s.radius) {
      EXPECT_LE(std::abs(s.g(p)), 1.0);
    }
  }
}

TEST(FitSupport, StopsAtAFoldWhereTheErrorExceedsTheTolerance) {
  Plane fold = NoisyPlane(0.0);
  for (auto& p : fold.points) p.z() = 0.5 * std::abs(p.x());  // a crease along x = 0
  const mesh_internal::PointIndex index(fold.points);
  const FitInput in{fold.points, fold.normals, index, 0.5, 100.0};
  const Support s = FitSupport(Eigen::Vector3d(0, 0, 0), 1.0, in);
  EXPECT_GE(s.radius, 1.0);
  EXPECT_LT(s.radius, 6.0);
}

TEST(FitSupport, BallInEmptySpaceReachesEnoughPoints) {
  const Plane plane = NoisyPlane(0.0);
  const mesh_internal::PointIndex index(plane.points);
  const FitInput in{plane.points, plane.normals, index, 0.5, 100.0};
  const Support s = FitSupport(Eigen::Vector3d(0, 0, 10), 0.5, in);
  EXPECT_GT(s.radius, 10.0);
  EXPECT_GE(s.point_count, kMinFitPoints);
  EXPECT_NEAR(s.g(s.center), -10.0, 0.5);  // outside, about its distance
}

// The fit FitSupport returns is eqs. (2)-(3) over exactly the points inside
// its ball, recomputed here from all points, and within ε there (eq. 6);
// on a curved surface, where the radius search doubles and bisects.
TEST(FitSupport, TheFitIsTheWeightedMeanOfThePointsInsideItsBallAndWithinTheTolerance) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    points.push_back(20.0 * n);
    normals.push_back(-n);
  }
  const mesh_internal::PointIndex index(points);
  const FitInput in{points, normals, index, /*epsilon=*/0.3, /*max_radius=*/100.0};
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(0.5, 0.2, 19.8), Eigen::Vector3d(12, -3, 15)}) {
    const Support s = FitSupport(c, 0.5, in);
    Eigen::Vector3d sum_n = Eigen::Vector3d::Zero(), sum_p = Eigen::Vector3d::Zero();
    double sum_w = 0.0, worst = 0.0;
    int inside = 0;
    for (size_t j = 0; j < points.size(); ++j) {
      const double d2 = (points[j] - c).squaredNorm();
      if (d2 >= s.radius * s.radius) continue;
      const double w = SupportWeight(d2, s.radius);
      sum_n += w * normals[j];
      sum_p += w * points[j];
      sum_w += w;
      ++inside;
    }
    for (size_t j = 0; j < points.size(); ++j) {
      if ((points[j] - c).norm() < s.radius) worst = std::max(worst, std::abs(s.g(points[j])));
    }
    EXPECT_GT(s.radius, 2.0);  // grown beyond the minimum, short of the sphere
    EXPECT_LT(s.radius, 20.0);
    EXPECT_EQ(s.point_count, inside);
    EXPECT_LT((s.m - sum_n.normalized()).norm(), 1e-12);
    EXPECT_LT((s.d - sum_p / sum_w).norm(), 1e-9);
    EXPECT_LE(worst, in.epsilon);
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
