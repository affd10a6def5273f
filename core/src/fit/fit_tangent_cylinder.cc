// The cylinder of a round between two flat faces: tangent to both planes,
// so its axis is their line of intersection moved onto the bisector, and
// its radius is the one value left to fit.
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "fit/fit_internal.h"
#include "fit/levenberg_marquardt.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

// Below this sine of the angle between the planes' normals there is no
// line of intersection to speak of.
constexpr double kMinSine = 1e-3;

// The axis of the tangent cylinder of radius r passes through
// base + r * per_radius along `direction`.
struct TangentAxis {
  Eigen::Vector3d direction;
  Eigen::Vector3d base;
  Eigen::Vector3d per_radius;  // perpendicular to direction
  Eigen::Vector3d unit_per_radius;
};

// State x = (r); one step, the radius.
class TangentProblem : public fit_internal::LeastSquaresProblem {
 public:
  TangentProblem(const FitInput& input, const TangentAxis& axis) : input_(input), axis_(axis) {}

  int NumSteps() const override { return 1; }

  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    const double r = x(0);
    const Eigen::Vector3d centre = axis_.base + r * axis_.per_radius;
    // One step value: scalar sums (a 1x1 fixed-size Eigen row trips gcc's
    // -Warray-bounds).
    double cost = 0.0, a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < input_.points.size(); ++i) {
      Eigen::Vector3d d = input_.points[i] - centre;
      d -= d.dot(axis_.direction) * axis_.direction;
      const double rho = d.norm();
      // On the axis the radial direction is undefined; any unit vector gives
      // a finite derivative.
      const Eigen::Vector3d u = rho > 0.0 ? Eigen::Vector3d(d / rho) : axis_.unit_per_radius;
      const double w = fit_internal::WeightAt(input_, i);
      const double residual = rho - r;
      const double derivative = -u.dot(axis_.per_radius) - 1.0;
      cost += w * residual * residual;
      a += w * derivative * derivative;
      b += w * residual * derivative;
    }
    jtj->setConstant(1, 1, a);
    jtr->setConstant(1, b);
    return cost;
  }

  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    return x + step;
  }

 private:
  const FitInput& input_;
  TangentAxis axis_;
};

}  // namespace

FitResult FitCylinderTangentToPlanes(const FitInput& input, const Plane& a, const Plane& b,
                                     std::array<int, 2> sides, double initial_radius,
                                     const FitParams& params) {
  const FitResult invalid = fit_internal::InvalidResult(Cylinder{});
  const Eigen::Vector3d na = a.normal.normalized(), nb = b.normal.normalized();
  const Eigen::Vector3d cross = na.cross(nb);
  if (input.points.size() < 2 || !cross.allFinite() || !(cross.norm() > kMinSine) ||
      !(initial_radius > 0.0) || !std::isfinite(initial_radius) || !a.point.allFinite() ||
      !b.point.allFinite() || std::abs(sides[0]) != 1 || std::abs(sides[1]) != 1) {
    return invalid;
  }
  // The axis point x(r) solves na.x = na.pa + sa r, nb.x = nb.pb + sb r and
  // lies in the plane across the axis through the points' centroid.
  TangentAxis axis{
      .direction = cross.normalized(), .base = {}, .per_radius = {}, .unit_per_radius = {}};
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : input.points) centroid += p;
  centroid /= static_cast<double>(input.points.size());
  Eigen::Matrix3d m;
  m.row(0) = na.transpose();
  m.row(1) = nb.transpose();
  m.row(2) = axis.direction.transpose();
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(m);
  axis.base =
      lu.solve(Eigen::Vector3d(na.dot(a.point), nb.dot(b.point), axis.direction.dot(centroid)));
  axis.per_radius = lu.solve(Eigen::Vector3d(sides[0], sides[1], 0.0));
  axis.unit_per_radius = axis.per_radius.normalized();

  const TangentProblem problem(input, axis);
  Eigen::VectorXd x0(1);
  x0(0) = initial_radius;
  const fit_internal::LmOutcome lm = params.refine ? MinimizeLevenbergMarquardt(problem, x0, params)
                                                   : fit_internal::LmOutcome{.x = x0};
  const double r = lm.x(0);
  if (!(r > 0.0) || !std::isfinite(r)) return invalid;
  FitResult result;
  result.surface = Cylinder{axis.base + r * axis.per_radius, axis.direction, r};
  result.valid = true;
  result.iterations = lm.iterations;
  fit_internal::SetDistanceErrors(input, &result);
  return result;
}

}  // namespace meshseg
