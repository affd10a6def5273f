// Sphere fit: algebraic initial fit (seed 002), then geometric refinement of
// r_i = |p_i - c| - R by Levenberg–Marquardt; state (c, R).
#include <cmath>

#include "fit/algebraic_sphere.h"
#include "fit/fit_internal.h"
#include "fit/levenberg_marquardt.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

using fit_internal::AccumulateNormalEquations;

class SphereProblem : public fit_internal::LeastSquaresProblem {
 public:
  explicit SphereProblem(const FitInput& input) : input_(input) {}
  int NumSteps() const override { return 4; }
  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    const Eigen::Vector3d c = x.head<3>();
    const double radius = x(3);
    return AccumulateNormalEquations<4>(
        input_,
        [&](std::size_t i, Eigen::Matrix<double, 1, 4>* row) {
          const Eigen::Vector3d v = input_.points[i] - c;
          const double len = v.norm();
          const Eigen::Vector3d u = len > 0.0 ? Eigen::Vector3d(v / len) : Eigen::Vector3d::Zero();
          *row << -u.transpose(), -1.0;
          return len - radius;
        },
        jtj, jtr);
  }
  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    return x + step;
  }

 private:
  const FitInput& input_;
};

}  // namespace

FitResult FitSphere(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  const auto init = FitAlgebraicSphere<3>(input.points, input.weights);
  Sphere sphere{init.center, init.radius};
  if (!init.valid) return InvalidResult(Sphere{});
  FitResult r;
  if (params.refine) {
    Eigen::VectorXd x0(4);
    x0 << init.center, init.radius;
    const LmOutcome lm = MinimizeLevenbergMarquardt(SphereProblem(input), x0, params);
    sphere = Sphere{lm.x.head<3>(), std::abs(lm.x(3))};
    r.iterations = lm.iterations;
  }
  if (!sphere.center.allFinite() || !std::isfinite(sphere.radius) || !(sphere.radius > 0.0)) {
    return InvalidResult(Sphere{});
  }
  r.surface = sphere;
  r.valid = true;
  SetDistanceErrors(input, &r);
  return r;
}

}  // namespace meshseg
