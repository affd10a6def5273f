// The solve of one least-squares round's normal equations (fit_control_points.h).
#ifndef MESHSEG_SUBDIV_SOLVE_NORMAL_EQUATIONS_H_
#define MESHSEG_SUBDIV_SOLVE_NORMAL_EQUATIONS_H_

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "absl/status/statusor.h"

namespace meshseg::subdiv_internal {

// Conjugate gradients stop at this residual relative to the right-hand side
// (about 25 iterations per decade on a 10,000-vertex control mesh; at 1e-6
// the rms per round already agrees with a direct solve to four digits).
inline constexpr double kSolveTolerance = 1e-8;
inline constexpr int kMaxSolveIterations = 2000;

struct NormalSolution {
  Eigen::VectorXd p;
  bool factored = false;  // conjugate gradients did not converge: LDLT solved it
};

// Returns the solution of normal * p = rhs (`normal` symmetric positive
// semi-definite): conjugate gradients with a diagonal (Jacobi)
// preconditioner started from `guess`, which the previous round (or the
// quasi-interpolation) left close to the solution: a few dozen products with
// the matrix instead of a Cholesky factorisation whose fill-in grows with
// the control mesh. A system that does not converge to kSolveTolerance in
// `max_iterations` is factored instead (SimplicialLDLT). `round` (0-based)
// names the fit round in errors.
// Errors: INTERNAL if the factorisation meets a zero pivot (a singular
// system) or the solution is not finite.
absl::StatusOr<NormalSolution> SolveNormalEquations(const Eigen::SparseMatrix<double>& normal,
                                                    const Eigen::VectorXd& rhs,
                                                    const Eigen::VectorXd& guess, int round,
                                                    int max_iterations = kMaxSolveIterations);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_SOLVE_NORMAL_EQUATIONS_H_
