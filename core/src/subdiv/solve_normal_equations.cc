#include "subdiv/solve_normal_equations.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include "absl/strings/str_cat.h"

namespace meshseg::subdiv_internal {

absl::StatusOr<NormalSolution> SolveNormalEquations(const Eigen::SparseMatrix<double>& normal,
                                                    const Eigen::VectorXd& rhs,
                                                    const Eigen::VectorXd& guess, int round,
                                                    int max_iterations) {
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kSolveTolerance);
  cg.setMaxIterations(max_iterations);
  cg.compute(normal);
  NormalSolution out{cg.solveWithGuess(rhs, guess)};
  if (cg.info() != Eigen::Success || !out.p.allFinite()) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) {
      return absl::InternalError(absl::StrCat("subdiv: the least-squares system of ",
                                              normal.rows() / 3,
                                              " control vertices cannot be factored"));
    }
    out.p = ldlt.solve(rhs);
    out.factored = true;
  }
  if (!out.p.allFinite()) {
    return absl::InternalError(
        absl::StrCat("subdiv: the least-squares solve failed in round ", round + 1));
  }
  return out;
}

}  // namespace meshseg::subdiv_internal
