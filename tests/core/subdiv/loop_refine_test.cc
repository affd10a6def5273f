#include "subdiv/loop_refine.h"

#include "bspline.h"
#include "control_meshes.h"

namespace meshseg::subdiv_internal {
namespace {

// Control heights of the lattice's bottom side (j = 0), a boundary crease.
double CreaseHeight(int i) { return std::sin(1.3 * i) + 0.2 * i; }

std::vector<double> BottomHeights(int nx) {
  std::vector<double> c;
  for (int i = 0; i <= nx; ++i) c.push_back(CreaseHeight(i));
  return c;
}

TEST(RefineLoop, SplitsEveryFaceAndSharpEdge) {
  const ControlMesh m = testing::CreasedOctahedron();
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const LoopLevel level = RefineLoop(m, *topo);
  EXPECT_EQ(level.mesh.vertices.size(), 6u + 12u);
  EXPECT_EQ(level.mesh.faces.size(), 32u);
  EXPECT_EQ(level.mesh.creases.size(), 10u);
  EXPECT_EQ(level.subdivision.rows(), 18);
  EXPECT_EQ(level.subdivision.cols(), 6);
  // Every rule is an affine combination.
  for (int r = 0; r < level.subdivision.rows(); ++r) {
    EXPECT_NEAR(level.subdivision.row(r).sum(), 1.0, 1e-15) << "row " << r;
  }
  // The corner stays; the dart (top pole) moves by Loop's valence-4 rule.
  EXPECT_EQ(level.mesh.vertices[1], m.vertices[1]);
  const double beta = LoopBeta(4);
  const Eigen::Vector3d pole =
      (1 - 4 * beta) * m.vertices[0] +
      beta * (m.vertices[1] + m.vertices[2] + m.vertices[3] + m.vertices[4]);
  EXPECT_LT((level.mesh.vertices[0] - pole).norm(), 1e-15);
}

TEST(RefineLoop, CreaseConvergesToCubicBSpline) {
  // The bottom side of the lattice is a boundary crease with corners at its
  // ends; away from the ends (u in [2, nx - 2]) its subdivided points approach
  // the uniform cubic B-spline of its control points with error O(4^-k)
  // (Lane-Riesenfeld), and x stays the curve parameter (linear precision).
  constexpr int kNx = 8;
  ControlMesh m =
      testing::Lattice(kNx, 2, [](int i, int j) { return j == 0 ? CreaseHeight(i) : 0.3 * i * j; });
  const std::vector<double> c = BottomHeights(kNx);
  std::vector<double> error;
  for (int level = 1; level <= 5; ++level) {
    auto topo = BuildControlTopology(m);
    ASSERT_TRUE(topo.ok()) << topo.status();
    m = RefineLoop(m, *topo).mesh;
    double max_error = 0.0;
    int on_crease = 0;
    for (const Eigen::Vector3d& p : m.vertices) {
      if (p.y() != 0.0 || p.x() < 2.0 || p.x() > kNx - 2.0) continue;
      max_error = std::max(max_error, std::abs(p.z() - testing::CubicBSpline(c, p.x())));
      ++on_crease;
    }
    EXPECT_EQ(on_crease, (kNx - 4) * (1 << level) + 1) << "level " << level;
    error.push_back(max_error);
  }
  for (size_t k = 1; k < error.size(); ++k) {
    EXPECT_LT(error[k], 0.3 * error[k - 1]) << "level " << k + 1;  // ratio 1/4 in the limit
  }
  EXPECT_LT(error.back(), 1e-3);
}

}  // namespace
}  // namespace meshseg::subdiv_internal
