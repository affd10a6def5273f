#include "reconstruct/seen_planes.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

constexpr int kLoop = 64;

// The bottom edge of a box [-1, 1]² × [0, 1] whose bottom is unseen: the loop
// runs round z = 0 on the walls, whose outward normals are horizontal.
void SquareLoop(std::vector<Eigen::Vector3d>* loop, std::vector<Eigen::Vector3d>* normals) {
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < kLoop / 4; ++k) {
      const double t = -1.0 + 2.0 * k / (kLoop / 4);
      const Eigen::Vector2d p[4] = {{t, -1}, {1, t}, {-t, 1}, {-1, -t}};
      const Eigen::Vector2d n[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
      loop->emplace_back(p[side].x(), p[side].y(), 0.0);
      normals->emplace_back(n[side].x(), n[side].y(), 0.0);
    }
  }
}

// Free vertices inside the box, 0.3 above its bottom (a membrane sagging
// into the solid): each goes onto the nearest face of the box, here the
// bottom, the plane of the loop.
TEST(BendOntoSeenPlanes, AVertexInsideAConvexHoleGoesOntoTheNearestPlane) {
  std::vector<Eigen::Vector3d> loop, normals;
  SquareLoop(&loop, &normals);
  std::vector<Eigen::Vector3d> free = {{0, 0, 0.3}, {0.5, -0.2, 0.3}, {-0.6, 0.6, 0.3}};
  const std::vector<Eigen::Vector3d> before = free;
  ASSERT_TRUE(BendOntoSeenPlanes(loop, normals, Eigen::Vector3d(0, 0, -1), &free));
  for (size_t i = 0; i < free.size(); ++i) {
    EXPECT_NEAR(free[i].z(), 0.0, 1e-9);
    EXPECT_NEAR((free[i] - before[i]).head<2>().norm(), 0.0, 1e-9);
  }
  // Nearer a wall than the bottom: onto the wall (x = 1).
  std::vector<Eigen::Vector3d> near_wall = {{0.9, 0.0, 0.5}};
  ASSERT_TRUE(BendOntoSeenPlanes(loop, normals, Eigen::Vector3d(0, 0, -1), &near_wall));
  EXPECT_NEAR(near_wall[0].x(), 1.0, 1e-9);
  EXPECT_NEAR(near_wall[0].z(), 0.5, 1e-9);
}

// One loop vertex on a fold of the seen surface (its normal points into the
// solid): its plane would cut off the whole loop, so it is no face of the
// hull, and the rest still bend the patch.
TEST(BendOntoSeenPlanes, AFoldAtTheBorderIsNoFaceOfTheHull) {
  std::vector<Eigen::Vector3d> loop, normals;
  SquareLoop(&loop, &normals);
  normals[5] = -normals[5];
  std::vector<Eigen::Vector3d> free = {{0, 0, 0.3}};
  ASSERT_TRUE(BendOntoSeenPlanes(loop, normals, Eigen::Vector3d(0, 0, -1), &free));
  EXPECT_NEAR(free[0].z(), 0.0, 1e-9);
}

// The rim of a bore (a circle whose seen surface faces the axis): every
// tangent plane cuts off the far side of the loop. The hole is concave and
// the patch is left as it is.
TEST(BendOntoSeenPlanes, ThePatchOfAConcaveHoleIsLeftAsItIs) {
  std::vector<Eigen::Vector3d> loop, normals;
  for (int k = 0; k < kLoop; ++k) {
    const double a = 2 * M_PI * k / kLoop;
    loop.emplace_back(std::cos(a), std::sin(a), 0.0);
    normals.emplace_back(-std::cos(a), -std::sin(a), 0.0);
  }
  std::vector<Eigen::Vector3d> free = {{0, 0, -0.2}, {0.3, 0.1, -0.1}};
  const std::vector<Eigen::Vector3d> before = free;
  EXPECT_FALSE(BendOntoSeenPlanes(loop, normals, Eigen::Vector3d(0, 0, 1), &free));
  EXPECT_EQ(free, before);
}

// A loop round a long, narrow strip (x in [-5, 5], y = ±0.1) that climbs
// one end up to z = 1: its tangent planes are the two parallel long walls
// (the ends give none), so the hull is open along x. A free vertex of the
// membrane lies in the loop's convex hull, so its clearance to the cap plane
// (z = 0) is at most the loop's depth below it, 1, and no vertex moves
// farther than that, whatever the hull's extent along x.
TEST(BendOntoSeenPlanes, OverParallelWallsAVertexMovesNoFartherThanTheLoopsDepth) {
  std::vector<Eigen::Vector3d> loop, normals;
  const auto height = [](double x) { return std::max(0.0, (x - 3.0) / 2.0); };
  for (int k = 0; k <= 40; ++k) {
    const double x = -5.0 + 0.25 * k;
    loop.emplace_back(x, -0.1, height(x));
    normals.emplace_back(0, -1, 0);
  }
  loop.emplace_back(5.0, 0.0, 1.0);
  normals.emplace_back(0, 0, 0);  // no tangent plane at the ends
  for (int k = 40; k >= 0; --k) {
    const double x = -5.0 + 0.25 * k;
    loop.emplace_back(x, 0.1, height(x));
    normals.emplace_back(0, 1, 0);
  }
  loop.emplace_back(-5.0, 0.0, 0.0);
  normals.emplace_back(0, 0, 0);
  std::vector<Eigen::Vector3d> free;
  for (int k = 0; k < 19; ++k) {
    const double x = -4.5 + 0.5 * k;
    free.emplace_back(x, 0.05 * ((k % 3) - 1), 0.5 * height(x));
  }
  const std::vector<Eigen::Vector3d> before = free;
  ASSERT_TRUE(BendOntoSeenPlanes(loop, normals, Eigen::Vector3d(0, 0, -1), &free));
  for (size_t i = 0; i < free.size(); ++i) {
    EXPECT_LE((free[i] - before[i]).norm(), 1.0 + 1e-9) << i;
    EXPECT_GE(free[i].z(), -1e-9) << i;  // never out past the cap plane
    EXPECT_LE(std::abs(free[i].y()), 0.1 + 1e-9) << i;  // nor past a wall
  }
}

// The same loop with one side climbing its wall to z = 0.5 (a quarter of the
// loop above the unseen bottom, tilted 5° from the axis given): the cap
// plane is still the bottom's, z = 0 facing down, as the consensus of the
// other three sides, not a plane tilted towards the climbing side.
TEST(SeenCapPlane, IsThePlaneMostOfTheLoopLiesOnWhenOneSideClimbsAWall) {
  std::vector<Eigen::Vector3d> loop, normals;
  SquareLoop(&loop, &normals);
  for (Eigen::Vector3d& p : loop) {
    if (p.x() == 1.0) p.z() = 0.5;
  }
  Eigen::Vector3d normal;
  double offset = 1.0;
  const Eigen::Vector3d tilted(std::sin(5 * M_PI / 180), 0.0, -std::cos(5 * M_PI / 180));
  ASSERT_TRUE(SeenCapPlane(loop, tilted, &normal, &offset));
  EXPECT_NEAR(normal.z(), -1.0, 1e-9);
  EXPECT_NEAR(offset, 0.0, 1e-9);
  // No plane through the loop within 45° of a sideways axis.
  EXPECT_FALSE(SeenCapPlane(loop, Eigen::Vector3d(0, 1, 0), &normal, &offset));
}

// A wall hanging past the unseen bottom: the whole of one side and a quarter
// of the next drop to z = -0.5 (20 of the 64 loop vertices, 31 % beyond the
// bottom, more than a fixed share of a tenth or a quarter would allow). The
// rim of the bottom is still most of the loop, so the cap plane is z = 0.
TEST(SeenCapPlane, AFoldHangingPastTheUnseenFaceLeavesItsPlaneTheCap) {
  std::vector<Eigen::Vector3d> loop, normals;
  SquareLoop(&loop, &normals);
  for (int k = 0; k < 20; ++k) loop[k].z() = -0.5;
  Eigen::Vector3d normal;
  double offset = 1.0;
  ASSERT_TRUE(SeenCapPlane(loop, Eigen::Vector3d(0, 0, -1), &normal, &offset));
  EXPECT_NEAR(normal.z(), -1.0, 1e-9);
  EXPECT_NEAR(offset, 0.0, 1e-9);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
