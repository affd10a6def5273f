#include "fit/levenberg_marquardt.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

namespace meshseg::fit_internal {
namespace {

constexpr double kInitialDamping = 1e-4;
constexpr double kMaxDamping = 1e12;   // beyond: no step lowers the cost
constexpr double kMinDamping = 1e-12;
constexpr double kMinRelativeStep = 1e-13;  // |step| / |x|: at machine precision

// The damped step -a^{-1} jtr by an LDLT of fixed size N: the axial fits'
// 5 and 6 step values, without the dynamic-size products' overhead. The
// factorisation is the same algorithm in the same order (unblocked, one
// column at a time), so the step is the same to the bit.
template <int N>
void FixedSizeStep(const Eigen::MatrixXd& a, const Eigen::VectorXd& jtr, Eigen::VectorXd* step) {
  const Eigen::Matrix<double, N, N> fixed = a;
  const Eigen::Matrix<double, N, 1> rhs = -jtr;
  *step = Eigen::LDLT<Eigen::Matrix<double, N, N>>(fixed).solve(rhs);
}

}  // namespace

LmOutcome MinimizeLevenbergMarquardt(const LeastSquaresProblem& problem,
                                     const Eigen::VectorXd& x0, const FitParams& params) {
  const int n = problem.NumSteps();
  LmOutcome out;
  out.x = x0;
  Eigen::MatrixXd jtj(n, n), jtj_new(n, n), a(n, n);
  Eigen::VectorXd jtr(n), jtr_new(n), step(n);
  // Kept across iterations: its storage is reused, the arithmetic is the same.
  Eigen::LDLT<Eigen::MatrixXd> ldlt(n);
  out.cost = problem.Evaluate(out.x, &jtj, &jtr);
  out.initial_cost = out.cost;
  if (!std::isfinite(out.cost)) return out;
  double damping = kInitialDamping;
  while (out.iterations < params.max_iterations) {
    if (out.cost == 0.0 || jtr.lpNorm<Eigen::Infinity>() == 0.0) {
      out.converged = true;
      break;
    }
    ++out.iterations;
    // Marquardt: damp each parameter in proportion to its curvature.
    const double floor = 1e-12 * std::max(jtj.diagonal().maxCoeff(), 1e-300);
    a = jtj;
    a.diagonal() += damping * jtj.diagonal().cwiseMax(floor);
    if (n == 6) {
      FixedSizeStep<6>(a, jtr, &step);
    } else if (n == 5) {
      FixedSizeStep<5>(a, jtr, &step);
    } else {
      ldlt.compute(a);
      step = ldlt.solve(-jtr);
    }
    double cost_new = std::numeric_limits<double>::infinity();
    Eigen::VectorXd x_new;
    if (step.allFinite()) {
      x_new = problem.Step(out.x, step);
      if (x_new.allFinite()) cost_new = problem.Evaluate(x_new, &jtj_new, &jtr_new);
    }
    if (std::isfinite(cost_new) && cost_new < out.cost) {
      const double decrease = (out.cost - cost_new) / out.cost;
      out.x = x_new;
      out.cost = cost_new;
      jtj.swap(jtj_new);
      jtr.swap(jtr_new);
      damping = std::max(damping * 0.1, kMinDamping);
      if (decrease < params.relative_tolerance ||
          step.norm() <= kMinRelativeStep * out.x.norm()) {
        out.converged = true;
        break;
      }
    } else {
      damping *= 10.0;
      if (damping > kMaxDamping) {
        out.converged = true;  // at a minimum to machine precision
        break;
      }
    }
  }
  return out;
}

}  // namespace meshseg::fit_internal
