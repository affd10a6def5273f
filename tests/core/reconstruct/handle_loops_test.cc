#include "reconstruct/handle_loops.h"

#include <vector>

#include <gtest/gtest.h>

#include "reconstruct/surface_mesh.h"
#include "tube_meshes.h"

namespace meshseg::reconstruct_internal {
namespace {

MeshGraph GraphOf(const TubeMesh& m) {
  return MakeMeshGraph(SurfaceMesh(m.vertices, m.triangles, "tubes")->tri);
}

// The meridian of a thin torus (8 edges of 2 × 0.05 sin(π / 8)): the
// shortest loop not contractible in a ball of radius 0.25 around any seed.
TEST(ShortLoops, FindsTheMeridianOfAThinTorus) {
  const TubeMesh torus = TorusTubeMesh(1.0, 0.05, 128, 8);
  const MeshGraph g = GraphOf(torus);
  const std::vector<HandleLoop> loops =
      ShortLoops(g, std::vector<double>(torus.vertices.size(), 0.5));
  ASSERT_FALSE(loops.empty());
  const double meridian = 8 * 2 * 0.05 * std::sin(M_PI / 8);
  EXPECT_NEAR(loops.front().length, meridian, 1e-9);
  EXPECT_EQ(loops.front().vertices.size(), 8u);
  for (const HandleLoop& l : loops) EXPECT_LE(l.length, 0.5);
}

// A disc-like ball finds nothing: a thick torus at the same bound, and the
// thin one below its meridian's length.
TEST(ShortLoops, FindsNoLoopLongerThanTheBound) {
  const TubeMesh thick = TorusTubeMesh(1.0, 0.3, 96, 32);
  EXPECT_TRUE(ShortLoops(GraphOf(thick), std::vector<double>(thick.vertices.size(), 0.5)).empty());
  const TubeMesh thin = TorusTubeMesh(1.0, 0.05, 128, 8);
  EXPECT_TRUE(ShortLoops(GraphOf(thin), std::vector<double>(thin.vertices.size(), 0.25)).empty());
}

// With `near`, only loops within the bound of a flagged vertex are found:
// a second thin torus's meridians (a separate component, loops as short) are
// not looked for when only the first torus is flagged.
TEST(ShortLoops, LooksOnlyNearTheFlaggedVertices) {
  TubeMesh both = TorusTubeMesh(1.0, 0.05, 128, 8);
  const size_t torus_vertices = both.vertices.size();
  both.Add(TorusTubeMesh(1.0, 0.05, 128, 8, Eigen::Vector3d(3, 0, 0)));
  const MeshGraph g = GraphOf(both);
  const std::vector<double> bound(both.vertices.size(), 0.5);
  std::vector<uint8_t> near(both.vertices.size(), 0);
  near[0] = 1;  // on the first torus
  const std::vector<HandleLoop> loops = ShortLoops(g, bound, near);
  ASSERT_FALSE(loops.empty());
  for (const HandleLoop& l : loops) {
    for (const int v : l.vertices) EXPECT_LT(v, static_cast<int>(torus_vertices));
  }
  bool second = false;
  for (const HandleLoop& l : ShortLoops(g, bound))
    second |= l.vertices[0] >= static_cast<int>(torus_vertices);
  EXPECT_TRUE(second);
}

// The covering: a capped rod (genus 0) as thin as the torus's tube, 3 long,
// against covering balls of radius about 4.25 × (0.25 + an edge) = 1.3: no
// ball holds both caps, and those that hold one are discs that cover its
// seeds, so its meridians (short, but every one separates) are not searched
// for; the torus's handle, whose balls are never discs, is searched as
// without a covering: the same loops as on the torus alone. (A search over
// every seed returns the rod's meridians too.)
TEST(ShortLoops, SkipsSeedsWhoseBallsLieInADisc) {
  const TubeMesh torus = TorusTubeMesh(1.0, 0.05, 128, 8);
  TubeMesh both = torus;
  both.Add(RodTubeMesh(0.05, 3.0, 8, 60, Eigen::Vector3d(3, 0, 0)));
  const std::vector<HandleLoop> alone =
      ShortLoops(GraphOf(torus), std::vector<double>(torus.vertices.size(), 0.5));
  const std::vector<HandleLoop> loops =
      ShortLoops(GraphOf(both), std::vector<double>(both.vertices.size(), 0.5));
  ASSERT_FALSE(alone.empty());
  ASSERT_EQ(loops.size(), alone.size());
  for (size_t i = 0; i < loops.size(); ++i) {
    EXPECT_EQ(loops[i].vertices, alone[i].vertices);
    EXPECT_DOUBLE_EQ(loops[i].length, alone[i].length);
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
