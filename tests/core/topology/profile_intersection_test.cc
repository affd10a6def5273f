#include "topology/profile_intersection.h"

#include <cmath>

#include <gtest/gtest.h>

namespace meshseg::topology_internal {
namespace {

constexpr double kTol = 1e-12;

Profile Line(double px, double py, double dx, double dy) {
  return {false, {px, py}, Eigen::Vector2d(dx, dy).normalized(), 0.0};
}
Profile Circle(double cx, double cy, double r) { return {true, {cx, cy}, {1.0, 0.0}, r}; }

TEST(IntersectProfiles, CrossingLinesMeetInOnePoint) {
  const auto q = IntersectProfiles(Line(0, 1, 1, 0), Line(2, 0, 0, 1), {0, 0}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR((*q - Eigen::Vector2d(2, 1)).norm(), 0.0, kTol);
}

TEST(IntersectProfiles, ParallelLinesDoNotMeet) {
  EXPECT_FALSE(IntersectProfiles(Line(0, 0, 1, 0), Line(0, 1, 1, 0), {0, 0}, 10.0).has_value());
}

TEST(IntersectProfiles, LineThroughCircleGivesThePointNearest) {
  // Plane t = 1 through a sphere of radius 2 at the origin: rho = sqrt(3).
  const auto q = IntersectProfiles(Line(1, 0, 0, 1), Circle(0, 0, 2), {1, 1}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->x(), 1.0, kTol);
  EXPECT_NEAR(q->y(), std::sqrt(3.0), kTol);
}

TEST(IntersectProfiles, NearlyTangentLineAndCircleMeetAtTheTouchingPoint) {
  // Torus tube of radius 4 centred (4, 14) over the plane t = 0 missed by 0.05.
  const auto q = IntersectProfiles(Line(-0.05, 0, 0, 1), Circle(4, 14, 4), {0, 13}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->x(), -0.025, kTol);
  EXPECT_NEAR(q->y(), 14.0, kTol);
  EXPECT_FALSE(IntersectProfiles(Line(-0.5, 0, 0, 1), Circle(4, 14, 4), {0, 13}, 0.1).has_value());
}

TEST(IntersectProfiles, TangentCirclesMeetOnTheCentreLine) {
  // Outside each other: radii 1 and 2, centres 3 apart.
  auto q = IntersectProfiles(Circle(0, 0, 1), Circle(3, 0, 2), {0, 0}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR((*q - Eigen::Vector2d(1, 0)).norm(), 0.0, kTol);
  // Nested: radius 1 inside radius 3, touching at (4, 0).
  q = IntersectProfiles(Circle(0, 0, 3), Circle(2, 0, 1), {0, 0}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR((*q - Eigen::Vector2d(3, 0)).norm(), 0.0, kTol);
}

TEST(IntersectProfiles, CrossingCirclesPickTheNearerPoint) {
  const auto q = IntersectProfiles(Circle(0, 0, 5), Circle(6, 0, 5), {3, -1}, 0.1);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR((*q - Eigen::Vector2d(3, -4)).norm(), 0.0, kTol);
}

}  // namespace
}  // namespace meshseg::topology_internal
