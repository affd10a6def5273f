#include "reconstruct/tube_rims.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tube_meshes.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kR = 15.0, kr = 5.0;  // torus radii
constexpr int kNu = 96, kNv = 32;

// The upper half (v in [0, π]) of the torus, as a HoleMesh with two border
// loops: the outer and the inner equator.
HoleMesh UpperHalfTorus() {
  const TubeMesh m = TorusTubeMesh(kR, kr, kNu, kNv);
  HoleMesh sm;
  std::vector<HoleMesh::Vertex_index> vertex;
  for (const Eigen::Vector3d& p : m.vertices) {
    vertex.push_back(sm.add_vertex(HoleKernel::Point_3(p.x(), p.y(), p.z())));
  }
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    if (static_cast<int>(t / 2) % kNv >= kNv / 2) continue;
    const auto& c = m.triangles[t];
    sm.add_face(vertex[c[0]], vertex[c[1]], vertex[c[2]]);
  }
  return sm;
}

// At both equators the seen half leaves straight down (the outgoing
// direction), and it curves on across them as the section does (1 / r),
// read from the normals 3 and 9 edges inside.
TEST(RimOf, TheEquatorsOfAHalfTorusLeaveStraightDownAtTheSectionsCurvature) {
  const HoleMesh sm = UpperHalfTorus();
  int loops = 0;
  std::vector<uint8_t> seen(sm.num_halfedges(), 0);
  for (const auto h : sm.halfedges()) {
    if (!sm.is_border(h) || seen[h]) continue;
    for (auto g = h; !seen[g]; g = sm.next(g)) seen[g] = 1;
    ++loops;
    const Rim rim = RimOf(sm, h, 1.0);
    ASSERT_EQ(rim.loop.size(), static_cast<size_t>(kNu));
    EXPECT_NEAR(rim.curvature, 1.0 / kr, 0.1 / kr);
    for (const Eigen::Vector3d& d : rim.out) EXPECT_GT(-d.z(), std::cos(3.0 * M_PI / 180.0));
  }
  EXPECT_EQ(loops, 2);
}

// A bore (radius 10, kNu cells round it) whose wall is seen from its rim at
// z = 0 up to z = 3.5 in steps of 0.5, where a 45° countersink opens it out:
// the section's edges are 0.5 long, so the rings 3 and 6 edges in lie on
// the straight wall and the one 9 edges in on the countersink. The wall
// does not curve across its rim (a cylinder), and the crease within reach
// does not read as curvature: the normal turns by 45° at the crease, which
// over the 3 edges to the far ring would read as 0.5 (0.24 read over both
// halves).
TEST(RimOf, ACreaseWithinReachOfTheRingsIsNoCurvatureOfTheWall) {
  constexpr double kBore = 10.0, kEdge = 0.5;
  std::vector<Eigen::Vector2d> section;  // (ρ, z) from the rim up
  for (int k = 0; k <= 7; ++k) section.emplace_back(kBore, k * kEdge);
  for (int k = 1; k <= 8; ++k) {
    section.emplace_back(kBore + k * kEdge / std::sqrt(2.0), 7 * kEdge + k * kEdge / std::sqrt(2.0));
  }
  HoleMesh sm;
  std::vector<HoleMesh::Vertex_index> vertex;
  for (int i = 0; i < kNu; ++i) {
    const double u = 2 * M_PI * i / kNu;
    for (const Eigen::Vector2d& q : section) {
      vertex.push_back(sm.add_vertex(
          HoleKernel::Point_3(q.x() * std::cos(u), q.x() * std::sin(u), q.y())));
    }
  }
  const int nv = static_cast<int>(section.size());
  const auto id = [&](int i, int j) { return vertex[(i % kNu) * nv + j]; };
  for (int i = 0; i < kNu; ++i) {
    for (int j = 0; j + 1 < nv; ++j) {
      // Faces towards the bore's axis (the solid's outside).
      sm.add_face(id(i, j), id(i, j + 1), id(i + 1, j + 1));
      sm.add_face(id(i, j), id(i + 1, j + 1), id(i + 1, j));
    }
  }
  for (const auto h : sm.halfedges()) {
    if (!sm.is_border(h) || sm.point(sm.target(h)).z() > 0.0) continue;
    const Rim rim = RimOf(sm, h, 1.0);
    ASSERT_EQ(rim.loop.size(), static_cast<size_t>(kNu));
    EXPECT_LT(std::abs(rim.curvature), 0.02);
    return;
  }
  FAIL() << "no border loop at the rim";
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
