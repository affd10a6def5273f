// Torus fit. Initial values by Kós et al. (seed 002): every normal line of a
// surface of revolution meets the axis, n·m + (v×n)·d = 0 for the axis line
// with direction d and moment m = p×d; (m, d) is the smallest eigenvector of
// Σ w z zᵀ, z = (n, v×n). The points, rotated into one half-plane through the
// axis, give a circle: minor radius, and tube-centre circle (centre on the
// axis, major radius). Then Levenberg–Marquardt on the geometric distance
// sqrt((rho − R)² + h²) − r. Needs normals.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "fit/algebraic_sphere.h"
#include "fit/fit_internal.h"
#include "fit/levenberg_marquardt.h"
#include "fit/torus_residual.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

constexpr double kCollinearRatio = 1e-12;
constexpr double kMinAxisWeight = 1e-6;  // |d| of the unit eigenvector: else no finite axis

// State x = (centre, axis, R, r); steps (centre (3), axis (2), R, r).
class TorusProblem : public fit_internal::LeastSquaresProblem {
 public:
  explicit TorusProblem(const FitInput& input) : input_(input) {}
  int NumSteps() const override { return 7; }
  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    const fit_internal::TorusFrame frame(x.head<3>(), x.segment<3>(3), x(6), x(7));
    // The residuals two points at a time (TorusResidualPair: the same
    // values), summed in point order as AccumulateNormalEquations does.
    const std::span<const Eigen::Vector3d> p = input_.points;
    fit_internal::NormalEquationSums<7> sums;
    Eigen::Matrix<double, 1, 7> row0, row1;
    double r0 = 0.0, r1 = 0.0;
    std::size_t i = 0;
    for (; i + 1 < p.size(); i += 2) {
      fit_internal::TorusResidualPair(frame, p[i], p[i + 1], &r0, &row0, &r1, &row1);
      sums.Add(fit_internal::WeightAt(input_, i), r0, row0);
      sums.Add(fit_internal::WeightAt(input_, i + 1), r1, row1);
    }
    if (i < p.size()) {
      r0 = fit_internal::TorusResidual(frame, p[i], &row0);
      sums.Add(fit_internal::WeightAt(input_, i), r0, row0);
    }
    return sums.Finish(jtj, jtr);
  }
  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    Eigen::VectorXd y = x;
    y.head<3>() += step.head<3>();
    y.segment<3>(3) = fit_internal::RotateAxis(x.segment<3>(3), step(3), step(4));
    y(6) += step(5);
    y(7) += step(6);
    return y;
  }

 private:
  const FitInput& input_;
};

// Seed 002 / Kós initial torus; false if the normals define no axis.
bool InitialTorus(const FitInput& input, const fit_internal::Moments& m, double s, Torus* t) {
  using namespace fit_internal;
  Eigen::Matrix<double, 6, 6> scatter = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> z;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d v = (input.points[i] - m.centroid) / s;
    const Eigen::Vector3d& n = input.normals[i];
    z << n, v.cross(n);
    scatter.noalias() += WeightAt(input, i) * z * z.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver(scatter);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::Matrix<double, 6, 1> mz = solver.eigenvectors().col(0);
  const double dn = mz.tail<3>().norm();
  if (!(dn > kMinAxisWeight)) return false;
  const Eigen::Vector3d d = mz.tail<3>() / dn;
  const Eigen::Vector3d moment = mz.head<3>() / dn;
  const Eigen::Vector3d p = m.centroid + s * d.cross(moment);  // axis point nearest the centroid

  // Points rotated into one half-plane through the axis: (rho, h).
  std::vector<Eigen::Vector2d> half_plane(input.points.size());
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    const Eigen::Vector3d v = input.points[i] - p;
    const double h = v.dot(d);
    half_plane[i] = Eigen::Vector2d((v - h * d).norm(), h);
  }
  const auto circle =
      FitAlgebraicSphere<2>(std::span<const Eigen::Vector2d>(half_plane), input.weights);
  if (!circle.valid) return false;
  *t = Torus{p + circle.center.y() * d, d, circle.center.x(), circle.radius};
  return true;
}

}  // namespace

FitResult FitTorus(const FitInput& input, const FitParams& params) {
  using namespace fit_internal;
  if (input.points.size() < 8 || !HasNormals(input)) return InvalidResult(Torus{});
  const Moments m = PointMoments(input);
  if (!(m.weight_sum > 0.0)) return InvalidResult(Torus{});
  const Eigen3 pca = SymmetricEigen(m.scatter);
  if (!(pca.values(1) > kCollinearRatio * pca.values(2))) return InvalidResult(Torus{});
  const double s = std::sqrt(pca.values.sum() / m.weight_sum);
  Torus torus;
  if (!InitialTorus(input, m, s, &torus)) return InvalidResult(Torus{});
  FitResult r;
  if (params.refine) {
    Eigen::VectorXd x0(8);
    x0 << torus.center, torus.axis_direction, torus.major_radius, torus.minor_radius;
    const LmOutcome lm = MinimizeLevenbergMarquardt(TorusProblem(input), x0, params);
    torus = Torus{lm.x.head<3>(), lm.x.segment<3>(3).normalized(), lm.x(6), std::abs(lm.x(7))};
    r.iterations = lm.iterations;
  }
  if (!torus.center.allFinite() || !torus.axis_direction.allFinite() ||
      !std::isfinite(torus.major_radius) || !std::isfinite(torus.minor_radius) ||
      !(torus.minor_radius > 0.0) || !(torus.major_radius >= 0.0)) {
    return InvalidResult(Torus{});
  }
  r.surface = torus;
  r.valid = true;
  SetDistanceErrors(input, &r);
  return r;
}

}  // namespace meshseg
