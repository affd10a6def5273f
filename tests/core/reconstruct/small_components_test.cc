#include "reconstruct/small_components.h"

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

// An octahedron (8 faces, vertices 0-5) and, after it, a tetrahedron
// (4 faces, vertices 6-9) far away.
IsoSurface OctahedronAndTetrahedron() {
  IsoSurface s;
  s.vertices = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}, {0, 0, 1},
                {0, 0, -1}, {9, 0, 0},  {10, 0, 0}, {9, 1, 0},  {9, 0, 1}};
  s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5},
                 {3, 1, 5}, {0, 3, 5}, {6, 8, 7}, {6, 7, 9}, {6, 9, 8}, {7, 8, 9}};
  s.to_smooth = {0, 1, 0, 0, 0, 1, 1, 0, 0, 0};
  return s;
}

TEST(DropSmallComponents, RemovesComponentsBelowTheFractionOfTheLargest) {
  IsoSurface s = OctahedronAndTetrahedron();
  EXPECT_EQ(DropSmallComponents(0.6, 0.0, &s), 1);  // 4 < 0.6 × 8
  EXPECT_EQ(s.triangles.size(), 8u);
  ASSERT_EQ(s.vertices.size(), 6u);
  EXPECT_EQ(s.vertices[5], Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(s.to_smooth, (std::vector<uint8_t>{0, 1, 0, 0, 0, 1}));
}

TEST(DropSmallComponents, KeepsEverythingAtZeroOrWhenLargeEnough) {
  IsoSurface s = OctahedronAndTetrahedron();
  EXPECT_EQ(DropSmallComponents(0.0, 0.0, &s), 0);
  EXPECT_EQ(DropSmallComponents(0.5, 0.0, &s), 0);  // 4 = 0.5 × 8
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.vertices.size(), 10u);
}

// Mean thickness 2 V / A: the octahedron's 2 (4/3) / (4 √3) = 0.385, the
// tetrahedron's 2 (1/6) / (3/2 + √3/2) = 0.141.
TEST(DropSmallComponents, RemovesAThinComponentButNeverTheLargest) {
  IsoSurface s = OctahedronAndTetrahedron();
  EXPECT_EQ(DropSmallComponents(0.1, 0.14, &s), 0);  // both thicker
  EXPECT_EQ(DropSmallComponents(0.1, 0.15, &s), 1);  // the tetrahedron is not
  EXPECT_EQ(s.triangles.size(), 8u);
  EXPECT_EQ(s.vertices.size(), 6u);
  IsoSurface t = OctahedronAndTetrahedron();
  EXPECT_EQ(DropSmallComponents(0.1, 1.0, &t), 1);  // the largest stays however thin
  EXPECT_EQ(t.triangles.size(), 8u);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
