// The stage's one nonlinear least-squares loop (Levenberg–Marquardt with
// Marquardt's diagonal scaling), used by the geometric refinement of the
// sphere, cylinder, cone and torus fits. A problem supplies the cost with its
// Gauss–Newton normal equations in a minimal tangent parametrisation, and
// how a tangent step moves the state (so axes stay unit vectors and no gauge
// freedom is left).
#ifndef MESHSEG_SRC_FIT_LEVENBERG_MARQUARDT_H_
#define MESHSEG_SRC_FIT_LEVENBERG_MARQUARDT_H_

#include <cstddef>

#include <Eigen/Core>

#include "fit/fit_internal.h"
#include "meshseg/fit.h"

namespace meshseg::fit_internal {

class LeastSquaresProblem {
 public:
  virtual ~LeastSquaresProblem() = default;
  // Number of values in a tangent step.
  virtual int NumSteps() const = 0;
  // Returns Σ w_i r_i(x)²; sets J^T W J and J^T W r (J = ∂r / ∂step at x,
  // NumSteps() columns).
  virtual double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                          Eigen::VectorXd* jtr) const = 0;
  // The state x moved by the tangent step.
  virtual Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const = 0;
};

struct LmOutcome {
  Eigen::VectorXd x;
  double initial_cost = 0.0;
  double cost = 0.0;
  int iterations = 0;
  bool converged = false;
};

// Minimises the problem's cost from x0 for at most params.max_iterations
// steps; stops when a step lowers the cost by less than
// params.relative_tolerance (relative) or is negligible next to |x|. Never returns a non-finite state: a
// step giving a non-finite cost is rejected.
LmOutcome MinimizeLevenbergMarquardt(const LeastSquaresProblem& problem,
                                     const Eigen::VectorXd& x0, const FitParams& params);

// Accumulates Σ w r², J^T W J and J^T W r over the input points for a
// problem with P step values; `residual(i, &row)` returns r_i and sets its
// Jacobian row. Fixed-size rows: no allocation per point.
template <int P, typename Residual>
double AccumulateNormalEquations(const FitInput& input, Residual&& residual,
                                 Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) {
  Eigen::Matrix<double, P, P> a = Eigen::Matrix<double, P, P>::Zero();
  Eigen::Matrix<double, P, 1> b = Eigen::Matrix<double, P, 1>::Zero();
  Eigen::Matrix<double, 1, P> row;
  double cost = 0.0;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const double w = WeightAt(input, i);
    const double r = residual(i, &row);
    cost += w * r * r;
    a.noalias() += w * row.transpose() * row;
    b.noalias() += (w * r) * row.transpose();
  }
  *jtj = a;
  *jtr = b;
  return cost;
}

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_LEVENBERG_MARQUARDT_H_
