#include "subdiv/limit_positions.h"

#include "bspline.h"
#include "control_meshes.h"

namespace meshseg::subdiv_internal {
namespace {

constexpr double kExact = 1e-12;  // rounding of a few hundred products

// The star of `v` in `m`: its faces, the sharp edges among them, v's corner
// tag. Refining it moves v and the points of v's edges exactly as refining
// `m` does, because Loop's rules for them read only v's 1-ring.
ControlMesh Star(const ControlMesh& m, const ControlTopology& topo, int v, int* v_in_star) {
  ControlMesh star;
  std::map<int, int> index;
  auto local = [&](int u) {
    auto [it, inserted] = index.try_emplace(u, static_cast<int>(star.vertices.size()));
    if (inserted) star.vertices.push_back(m.vertices[u]);
    return it->second;
  };
  *v_in_star = local(v);
  for (const auto& f : m.faces) {
    if (f[0] != v && f[1] != v && f[2] != v) continue;
    star.faces.push_back({local(f[0]), local(f[1]), local(f[2])});
  }
  for (int e : topo.vertex_edges[v]) {
    if (topo.sharp[e]) star.creases.push_back({local(topo.edges[e][0]), local(topo.edges[e][1])});
  }
  if (topo.kind[v] == VertexKind::kCorner) star.corners.push_back(*v_in_star);
  return star;
}

TEST(LimitMasks, RegularVertexHasBoxSplineValues) {
  // Loop's surface over a regular lattice is the quartic box spline M_222
  // (Loop 1987); its values at the lattice points are 1/2 at the centre and
  // 1/12 at the six neighbours.
  const ControlMesh m = testing::Lattice(4, 4, [](int, int) { return 0.0; });
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const SparseMatrix masks = LimitMasks(*topo);
  const int centre = 2 * 5 + 2;
  EXPECT_NEAR(masks.coeff(centre, centre), 0.5, kExact);
  for (int nb : {centre - 1, centre + 1, centre - 5, centre + 5, centre - 6, centre + 6}) {
    EXPECT_NEAR(masks.coeff(centre, nb), 1.0 / 12.0, kExact) << "neighbour " << nb;
  }
  EXPECT_NEAR(masks.row(centre).sum(), 1.0, kExact);
  // A crease vertex: the cubic B-spline's 1/6, 2/3, 1/6.
  EXPECT_NEAR(masks.coeff(2, 2), 2.0 / 3.0, kExact);
  EXPECT_NEAR(masks.coeff(2, 1), 1.0 / 6.0, kExact);
  EXPECT_NEAR(masks.coeff(2, 3), 1.0 / 6.0, kExact);
  EXPECT_NEAR(masks.coeff(2, 7), 0.0, kExact);
  EXPECT_NEAR(masks.coeff(0, 0), 1.0, kExact);  // corner
}

TEST(SampleLimitSurface, RegularPatchReproducesQuadraticsAsBoxSpline) {
  // For quadratic control heights q(i, j) the box spline is q(x, y) + c0 with
  // c0 = sum over lattice points of M_222 * Q = (4a + 2b + 4c) / 12 for
  // Q = a x^2 + b x y + c y^2: every limit point of the regular part (two
  // control rings from the boundary, the masks' reach at level 2) lies on it.
  constexpr double a = 0.3, b = -0.2, c = 0.1;
  auto q = [&](double x, double y) { return a * x * x + b * x * y + c * y * y + 0.5 * x - y; };
  constexpr int kN = 8;
  const ControlMesh m = testing::Lattice(kN, kN, q);
  auto limit = SampleLimitSurface(m, 2);
  ASSERT_TRUE(limit.ok()) << limit.status();
  const double c0 = (4 * a + 2 * b + 4 * c) / 12.0;
  int checked = 0;
  for (const Eigen::Vector3d& p : limit->mesh.vertices) {
    if (std::min({p.x(), p.y(), kN - p.x(), kN - p.y()}) < 2.0 - 1e-9) continue;
    EXPECT_NEAR(p.z(), q(p.x(), p.y()) + c0, kExact) << p.transpose();
    ++checked;
  }
  EXPECT_EQ(checked, 17 * 17);
}

TEST(SampleLimitSurface, CreaseLimitIsCubicBSpline) {
  constexpr int kN = 8;
  auto h = [](int i) { return std::cos(0.9 * i) * (1.0 + 0.1 * i); };
  const ControlMesh m =
      testing::Lattice(kN, 3, [&](int i, int j) { return j == 0 ? h(i) : 0.5 * j - 0.1 * i; });
  std::vector<double> ctrl;
  for (int i = 0; i <= kN; ++i) ctrl.push_back(h(i));
  auto limit = SampleLimitSurface(m, 3);
  ASSERT_TRUE(limit.ok()) << limit.status();
  int checked = 0;
  for (const Eigen::Vector3d& p : limit->mesh.vertices) {
    if (std::abs(p.y()) > kExact || p.x() < 2.0 - 1e-9 || p.x() > kN - 2.0 + 1e-9) continue;
    EXPECT_NEAR(p.z(), testing::CubicBSpline(ctrl, p.x()), kExact) << p.transpose();
    ++checked;
  }
  EXPECT_EQ(checked, (kN - 4) * 8 + 1);
}

TEST(LimitMasks, AgreeWithRepeatedSubdivision) {
  // Each vertex kind of the creased octahedron (smooth valence 4, dart,
  // crease, tagged and three-crease corner), with the octahedron subdivided
  // once so valence 6 appears too: refine the vertex's star 60 times, where
  // the subdominant eigenvalue (at most 5/8 for these valences) leaves
  // < 1e-12 of the start.
  auto base_topo = BuildControlTopology(testing::CreasedOctahedron());
  ASSERT_TRUE(base_topo.ok());
  const ControlMesh m = RefineLoop(testing::CreasedOctahedron(), *base_topo).mesh;
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const std::vector<Eigen::Vector3d> limit = Apply(LimitMasks(*topo), m.vertices);
  for (int v = 0; v < static_cast<int>(m.vertices.size()); ++v) {
    int local = 0;
    ControlMesh star = Star(m, *topo, v, &local);
    for (int level = 0; level < 60; ++level) {
      auto star_topo = BuildControlTopology(star);
      ASSERT_TRUE(star_topo.ok()) << star_topo.status();
      ControlMesh fine = RefineLoop(star, *star_topo).mesh;
      auto fine_topo = BuildControlTopology(fine);
      ASSERT_TRUE(fine_topo.ok()) << fine_topo.status();
      star = Star(fine, *fine_topo, local, &local);
    }
    EXPECT_LT((star.vertices[local] - limit[v]).norm(), 1e-9) << "vertex " << v;
  }
}

}  // namespace
}  // namespace meshseg::subdiv_internal
