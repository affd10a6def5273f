#include "subdiv/fit_control_points.h"

#include "control_meshes.h"
#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

TEST(QuasiInterpolate, IsSeedEquationOneAtRegularVertices) {
  // Seed 004 eq. (1): v <- (1 - k gamma) v + gamma sum v_j, gamma = -1/(2k).
  const ControlMesh m = testing::Lattice(4, 4, [](int i, int j) { return std::sin(i + 2.0 * j); });
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const std::vector<Eigen::Vector3d> qi = QuasiInterpolate(m, *topo);
  const int v = 2 * 5 + 2;
  const double gamma = -1.0 / 12.0;
  Eigen::Vector3d expected = (1 - 6 * gamma) * m.vertices[v];
  for (int nb : {v - 1, v + 1, v - 5, v + 5, v - 6, v + 6}) expected += gamma * m.vertices[nb];
  EXPECT_LT((qi[v] - expected).norm(), 1e-12);
  EXPECT_EQ(qi[0], m.vertices[0]);  // a corner stays
}

TEST(FitControlPoints, RecoversAControlMeshFromItsOwnLimitSurface) {
  // Data sampled on the limit surface of a known control mesh: the fit
  // started from the data's nearest vertices must come back to it (the
  // least-squares problem has an exact solution).
  ControlMesh truth = testing::CreasedOctahedron();
  auto dense = SampleLimitSurface(truth, 3);
  ASSERT_TRUE(dense.ok()) << dense.status();
  ControlMesh start = truth;
  for (auto& v : start.vertices) v *= 1.1;
  auto fit = FitControlPoints(start, dense->mesh.vertices, 3, 8, 0.0, 0.1);
  ASSERT_TRUE(fit.ok()) << fit.status();
  EXPECT_LT(fit->rms_distance, 1e-3) << "rounds " << fit->rms_per_round.size();
  for (size_t v = 0; v < truth.vertices.size(); ++v) {
    EXPECT_LT((fit->vertices[v] - truth.vertices[v]).norm(), 1e-2) << "vertex " << v;
  }
}

}  // namespace
}  // namespace meshseg::subdiv_internal
