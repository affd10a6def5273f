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

// The sums of the normal equations of a problem with P step values, one
// point at a time: Σ w r², J^T W J and J^T W r. J^T W J is symmetric: only
// its lower triangle is summed, entry (k, l), k >= l, as (w row_k) row_l,
// the product and order of terms of the full outer product w row^T row, so
// each entry is the same to the bit; the upper triangle is then copied
// from it (the LDLT of the steps reads the lower triangle only).
template <int P>
class NormalEquationSums {
 public:
  void Add(double w, double r, const Eigen::Matrix<double, 1, P>& row) {
    cost_ += w * r * r;
    const double wr = w * r;
    int e = 0;
    for (int k = 0; k < P; ++k) {
      const double wk = w * row(k);
      for (int l = 0; l <= k; ++l) a_[e++] += wk * row(l);
      b_[k] += wr * row(k);
    }
  }
  // Sets J^T W J and J^T W r; returns Σ w r².
  double Finish(Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const {
    jtj->resize(P, P);
    jtr->resize(P);
    int e = 0;
    for (int k = 0; k < P; ++k) {
      for (int l = 0; l <= k; ++l, ++e) (*jtj)(k, l) = (*jtj)(l, k) = a_[e];
      (*jtr)(k) = b_[k];
    }
    return cost_;
  }

 private:
  double a_[P * (P + 1) / 2] = {};
  double b_[P] = {};
  double cost_ = 0.0;
};

// Accumulates Σ w r², J^T W J and J^T W r over the input points for a
// problem with P step values (NormalEquationSums, in point order);
// `residual(i, &row)` returns r_i and sets its Jacobian row. Fixed-size
// rows: no allocation per point.
template <int P, typename Residual>
double AccumulateNormalEquations(const FitInput& input, Residual&& residual,
                                 Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) {
  NormalEquationSums<P> sums;
  Eigen::Matrix<double, 1, P> row;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const double r = residual(i, &row);
    sums.Add(WeightAt(input, i), r, row);
  }
  return sums.Finish(jtj, jtr);
}

}  // namespace meshseg::fit_internal

#endif  // MESHSEG_SRC_FIT_LEVENBERG_MARQUARDT_H_
