#include "subdiv/data_guard.h"

#include "control_meshes.h"
#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

constexpr int kN = 4;  // Lattice(kN, kN): (kN + 1)^2 vertices

int At(int i, int j) { return j * (kN + 1) + i; }

TEST(DataGuard, TopsUpTheWeightOfVerticesTheDataHardlyReach) {
  // Data weight 1 on every vertex but (2, 2) (none) and (1, 1) (0.1): with
  // fraction 1/4 the floor is 0.25, so those two get weights 0.25 and 0.15
  // on their umbrella vectors; the others none.
  const ControlMesh m = testing::Lattice(kN, kN, [](int i, int j) { return 0.1 * i * j; });
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  const int n = static_cast<int>(m.vertices.size());
  Eigen::VectorXd diagonal = Eigen::VectorXd::Ones(3 * n);
  diagonal.segment<3>(3 * At(2, 2)).setZero();
  diagonal.segment<3>(3 * At(1, 1)).setConstant(0.1);
  const Eigen::SparseMatrix<double> data = Eigen::SparseMatrix<double>(diagonal.asDiagonal());
  Eigen::VectorXd prior(3 * n);
  for (int v = 0; v < n; ++v) prior.segment<3>(3 * v) = m.vertices[v];
  const GuardTerm guard = DataGuard(UmbrellaOperator(*topo, n), data, prior, 0.25);
  EXPECT_EQ(guard.guarded, 2);
  EXPECT_LT((guard.matrix * prior - guard.rhs).norm(), 1e-12);
  // The energy (P - prior)^T M (P - prior) of moving (2, 2) alone by d:
  // its own umbrella vector changes by d, that of its neighbour (1, 1)
  // (valence 6) by -d / 6; no other guarded vertex sees it.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(3 * n);
  d.segment<3>(3 * At(2, 2)) = Eigen::Vector3d(0.3, -0.2, 0.5);
  const double expected = (0.25 + 0.15 / 36.0) * d.squaredNorm();
  EXPECT_NEAR(d.dot(guard.matrix * d), expected, 1e-12);
  // A translation changes no umbrella vector: the guard holds shape, not
  // place, so a guarded vertex moves with its neighbours.
  Eigen::VectorXd shift(3 * n);
  for (int v = 0; v < n; ++v) shift.segment<3>(3 * v) = Eigen::Vector3d(0.2, 0.0, 1.0);
  EXPECT_NEAR(shift.dot(guard.matrix * shift), 0.0, 1e-12);
  // Fraction 0: no guard.
  EXPECT_EQ(DataGuard(UmbrellaOperator(*topo, n), data, prior, 0.0).guarded, 0);
}

}  // namespace
}  // namespace meshseg::subdiv_internal
