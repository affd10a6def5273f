#include "fit/axial_fit.h"

#include <cmath>
#include <limits>
#include <vector>

#include <tbb/parallel_for.h>

#include "fit/algebraic_sphere.h"
#include "fit/fit_internal.h"

namespace meshseg::fit_internal {
namespace {

// State x = (origin, axis, radius, angle); steps (s1, s2, t1, t2, radius[, angle]).
class AxialProblem : public LeastSquaresProblem {
 public:
  AxialProblem(const FitInput& input, bool fit_angle) : input_(input), fit_angle_(fit_angle) {}
  int NumSteps() const override { return fit_angle_ ? 6 : 5; }

  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    if (fit_angle_) return Accumulate<6>(x, jtj, jtr);
    return Accumulate<5>(x, jtj, jtr);
  }

  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    const Eigen::Vector3d a = x.segment<3>(3);
    Eigen::Vector3d b1, b2;
    PerpendicularBasis(a, &b1, &b2);
    Eigen::VectorXd y = x;
    y.head<3>() += step(0) * b1 + step(1) * b2;
    y.segment<3>(3) = RotateAxis(a, b1, b2, step(2), step(3));
    y(6) += step(4);
    if (fit_angle_) y(7) += step(5);
    return y;
  }

 private:
  template <int P>
  double Accumulate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const {
    const AxialFrame frame(x.head<3>(), x.segment<3>(3), x(6), x(7));
    // AccumulateNormalEquations with the residuals made two points at a
    // time (AxialResidualPair: the same values), summed in point order.
    const std::span<const Eigen::Vector3d> p = input_.points;
    NormalEquationSums<P> sums;
    Eigen::Matrix<double, 1, P> row0, row1;
    double r0 = 0.0, r1 = 0.0;
    std::size_t i = 0;
    for (; i + 1 < p.size(); i += 2) {
      AxialResidualPair<P>(frame, p[i], p[i + 1], &r0, &row0, &r1, &row1);
      sums.Add(WeightAt(input_, i), r0, row0);
      sums.Add(WeightAt(input_, i + 1), r1, row1);
    }
    if (i < p.size()) {
      r0 = AxialResidual<P>(frame, p[i], &row0);
      sums.Add(WeightAt(input_, i), r0, row0);
    }
    return sums.Finish(jtj, jtr);
  }

  const FitInput& input_;
  bool fit_angle_;
};

Eigen::VectorXd ToState(const AxialSurface& s) {
  Eigen::VectorXd x(8);
  x << s.origin, s.axis, s.radius, s.angle;
  return x;
}

}  // namespace

AxialFrame::AxialFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double radius,
                       double angle)
    : origin(origin),
      axis(axis),
      radius(radius),
      cos_angle(std::cos(angle)),
      sin_angle(std::sin(angle)) {
  PerpendicularBasis(axis, &b1, &b2);
}

bool FitCrossSection(const FitInput& input, const Eigen::Vector3d& centroid,
                     const Eigen::Vector3d& axis, AxialSurface* out) {
  Eigen::Vector3d b1, b2;
  PerpendicularBasis(axis, &b1, &b2);
  std::vector<Eigen::Vector2d> flat(input.points.size());
  for (std::size_t i = 0; i < flat.size(); ++i) {
    const Eigen::Vector3d d = input.points[i] - centroid;
    flat[i] = Eigen::Vector2d(d.dot(b1), d.dot(b2));
  }
  const auto circle = FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(flat), input.weights);
  if (!circle.valid) return false;
  out->origin = centroid + circle.center.x() * b1 + circle.center.y() * b2;
  out->axis = axis;
  out->radius = circle.radius;
  out->angle = 0.0;
  return true;
}

LmOutcome RefineAxial(const FitInput& input, const Eigen::Vector3d& centroid, bool fit_angle,
                      const FitParams& params, AxialSurface* s) {
  const AxialProblem problem(input, fit_angle);
  LmOutcome lm = MinimizeLevenbergMarquardt(problem, ToState(*s), params);
  AxialSurface r;
  r.origin = lm.x.head<3>();
  r.axis = lm.x.segment<3>(3).normalized();
  r.radius = lm.x(6);
  r.angle = lm.x(7);
  // Slide the origin along the axis next to the data; the radius follows
  // the generator.
  const double shift = (centroid - r.origin).dot(r.axis);
  r.origin += shift * r.axis;
  r.radius += shift * std::tan(r.angle);
  *s = r;
  return lm;
}

double AxialCost(const FitInput& input, const AxialSurface& s) {
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
  return AxialProblem(input, true).Evaluate(ToState(s), &jtj, &jtr);
}

double BestAxialFit(const FitInput& input, const Eigen::Vector3d& centroid,
                    std::span<const AxialSurface> starts, bool fit_angle,
                    const FitParams& params, AxialSurface* best, int* iterations) {
  // The starts share nothing but the input: each is refined on a core of
  // its own, and the best is picked in start order afterwards (the first of
  // equal costs, as a serial loop would).
  struct Refined {
    AxialSurface surface;
    double cost = 0.0;
    int used = 0;
  };
  std::vector<Refined> refined(starts.size());
  tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t k) {
    Refined& r = refined[k];
    r.surface = starts[k];
    if (params.refine) {
      const LmOutcome lm = RefineAxial(input, centroid, fit_angle, params, &r.surface);
      r.used = lm.iterations;
      r.cost = lm.cost;
    } else {
      r.cost = AxialCost(input, r.surface);
    }
  });
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Refined& r : refined) {
    if (r.cost < best_cost) {
      best_cost = r.cost;
      *best = r.surface;
      *iterations = r.used;
    }
  }
  return best_cost;
}

}  // namespace meshseg::fit_internal
