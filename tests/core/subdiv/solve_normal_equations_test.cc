#include "subdiv/solve_normal_equations.h"

#include <vector>

#include <Eigen/Dense>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace meshseg::subdiv_internal {
namespace {

using ::testing::HasSubstr;

// The path Laplacian (tridiagonal 2, -1) of n nodes plus `shift` times the
// identity: its eigenvalues are shift + 4 sin^2(k pi / (2 (n + 1))), so
// with a small shift its condition number is about 4 / (shift + (pi / n)^2).
Eigen::SparseMatrix<double> ShiftedPathLaplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + shift);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(SolveNormalEquations, ConjugateGradientsSolveAWellConditionedSystem) {
  // Shift 1: condition number below 5, CG converges in a few iterations.
  const Eigen::SparseMatrix<double> a = ShiftedPathLaplacian(60, 1.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(60, -1.0, 2.0);
  auto r = SolveNormalEquations(a, a * x, Eigen::VectorXd::Zero(60), 0);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_FALSE(r->factored);
  EXPECT_LT((r->p - x).norm(), 1e-6 * x.norm());
}

TEST(SolveNormalEquations, FallsBackToLdltWhenConjugateGradientsDoNotConverge) {
  // 300 nodes, shift 1e-9: condition number about 4e4 / 1.1, far more than
  // conjugate gradients reduce the residual by 1e-8 in a budget of 5
  // iterations (each step reaches one node further along the path, and the
  // right-hand side below needs all 300). The factorisation solves it exactly
  // up to rounding times the condition number.
  constexpr int kN = 300;
  const Eigen::SparseMatrix<double> a = ShiftedPathLaplacian(kN, 1e-9);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(kN);
  b[0] = 1.0;
  auto r = SolveNormalEquations(a, b, Eigen::VectorXd::Zero(kN), 0, /*max_iterations=*/5);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->factored);
  const Eigen::VectorXd dense = Eigen::MatrixXd(a).ldlt().solve(b);
  EXPECT_LT((r->p - dense).norm(), 1e-6 * dense.norm());
  EXPECT_LT((a * r->p - b).norm(), 1e-9);
  // With the default budget the same system converges without the fallback.
  auto cg = SolveNormalEquations(a, b, Eigen::VectorXd::Zero(kN), 0);
  ASSERT_TRUE(cg.ok()) << cg.status();
  EXPECT_FALSE(cg->factored);
  EXPECT_LT((cg->p - dense).norm(), 1e-4 * dense.norm());
}

TEST(SolveNormalEquations, ReportsASingularSystem) {
  // A control vertex no data point and no smoothing term reaches has a zero
  // row: CG does not converge on the inconsistent right-hand side and the
  // factorisation meets a zero pivot.
  Eigen::SparseMatrix<double> a = ShiftedPathLaplacian(6, 1.0);
  for (int i = 0; i < 6; ++i) {
    a.coeffRef(3, i) = 0.0;
    a.coeffRef(i, 3) = 0.0;
  }
  Eigen::VectorXd b = Eigen::VectorXd::Ones(6);
  auto r = SolveNormalEquations(a, b, Eigen::VectorXd::Zero(6), 2);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInternal);
  EXPECT_THAT(r.status().message(), HasSubstr("system of 2 control vertices cannot be factored"));
}

}  // namespace
}  // namespace meshseg::subdiv_internal
