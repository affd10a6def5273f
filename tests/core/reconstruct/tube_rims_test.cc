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

}  // namespace
}  // namespace meshseg::reconstruct_internal
