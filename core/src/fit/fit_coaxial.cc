// Cylinders and cones on one axis, fitted together: the problem of
// axial_fit.cc with the axis shared and a (radius, angle) pair per member.
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>

#include "fit/axial_fit.h"
#include "fit/fit_internal.h"
#include "fit/levenberg_marquardt.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

using fit_internal::AxialFrame;

constexpr double kMinTanAngle = 1e-12;  // below, the "cone" is a cylinder (as FitCone)

bool IsCone(const CoaxialMember& m) { return m.type == SurfaceType::kCone; }

// State x = (origin, axis, then radius and angle of each member); steps
// (s1, s2, t1, t2, then radius and, for a cone, angle of each member).
class CoaxialProblem : public fit_internal::LeastSquaresProblem {
 public:
  explicit CoaxialProblem(std::span<const CoaxialMember> members) : members_(members) {
    int next = 4;
    for (const CoaxialMember& m : members_) {
      first_step_.push_back(next);
      next += IsCone(m) ? 2 : 1;
    }
    num_steps_ = next;
  }

  int NumSteps() const override { return num_steps_; }

  double Evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jtj,
                  Eigen::VectorXd* jtr) const override {
    jtj->setZero(num_steps_, num_steps_);
    jtr->setZero(num_steps_);
    double cost = 0.0;
    for (std::size_t j = 0; j < members_.size(); ++j) {
      const AxialFrame frame(x.head<3>(), x.segment<3>(3), x(6 + 2 * j), x(7 + 2 * j));
      cost += IsCone(members_[j]) ? Add<6>(j, frame, jtj, jtr) : Add<5>(j, frame, jtj, jtr);
    }
    return cost;
  }

  Eigen::VectorXd Step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override {
    const Eigen::Vector3d a = x.segment<3>(3);
    Eigen::Vector3d b1, b2;
    fit_internal::PerpendicularBasis(a, &b1, &b2);
    Eigen::VectorXd y = x;
    y.head<3>() += step(0) * b1 + step(1) * b2;
    y.segment<3>(3) = fit_internal::RotateAxis(a, step(2), step(3));
    for (std::size_t j = 0; j < members_.size(); ++j) {
      y(6 + 2 * j) += step(first_step_[j]);
      if (IsCone(members_[j])) y(7 + 2 * j) += step(first_step_[j] + 1);
    }
    return y;
  }

 private:
  // Adds member j's normal equations: its rows have the four axis steps,
  // then its own radius (and angle) step.
  template <int P>
  double Add(std::size_t j, const AxialFrame& frame, Eigen::MatrixXd* jtj,
             Eigen::VectorXd* jtr) const {
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    const FitInput& input = members_[j].input;
    const double cost = fit_internal::AccumulateNormalEquations<P>(
        input,
        [&](std::size_t i, Eigen::Matrix<double, 1, P>* row) {
          return fit_internal::AxialResidual<P>(frame, input.points[i], row);
        },
        &a, &b);
    int index[P];
    for (int k = 0; k < P; ++k) index[k] = k < 4 ? k : first_step_[j] + (k - 4);
    for (int r = 0; r < P; ++r) {
      (*jtr)(index[r]) += b(r);
      for (int c = 0; c < P; ++c) (*jtj)(index[r], index[c]) += a(r, c);
    }
    return cost;
  }

  std::span<const CoaxialMember> members_;
  std::vector<int> first_step_;
  int num_steps_ = 4;
};

// Weighted least-squares line rho = radius + h tan(angle) of the member's points
// about the axis (o, a); a cylinder's angle is 0.
void StartMember(const CoaxialMember& m, const Eigen::Vector3d& o, const Eigen::Vector3d& a,
                 double* radius, double* angle) {
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < m.input.points.size(); ++i) {
    const Eigen::Vector3d v = m.input.points[i] - o;
    const double h = v.dot(a);
    const double rho = (v - h * a).norm();
    const Eigen::Vector2d row(1.0, h);
    const double w = fit_internal::WeightAt(m.input, i);
    normal.noalias() += w * row * row.transpose();
    rhs += (w * rho) * row;
  }
  *angle = 0.0;
  *radius = rhs(0) / normal(0, 0);
  if (!IsCone(m)) return;
  const Eigen::Vector2d line = normal.ldlt().solve(rhs);
  if (line.allFinite()) {
    *radius = line(0);
    *angle = std::atan(line(1));
  }
}

// The member's surface on the fitted axis (o, a) with its radius and angle;
// false for a cone whose half angle is ~0.
bool MemberSurface(const CoaxialMember& m, const Eigen::Vector3d& o, const Eigen::Vector3d& a,
                   double radius, double angle, Surface* out) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : m.input.points) centroid += p;
  centroid /= static_cast<double>(m.input.points.size());
  // The axis point nearest the centroid, and the radius there.
  const double shift = (centroid - o).dot(a);
  const Eigen::Vector3d near = o + shift * a;
  radius += shift * std::tan(angle);
  if (!IsCone(m)) {
    *out = Cylinder{near, a, radius};
    return near.allFinite() && std::isfinite(radius);
  }
  double t = std::tan(angle);
  Eigen::Vector3d axis = a;
  if (t < 0.0) {
    t = -t;
    axis = -axis;
  }
  if (!std::isfinite(t) || !(t > kMinTanAngle)) return false;
  const Cone cone{near - (radius / t) * axis, axis, std::atan(t)};
  *out = cone;
  return cone.apex.allFinite();
}

std::vector<FitResult> AllInvalid(std::span<const CoaxialMember> members) {
  std::vector<FitResult> out;
  for (const CoaxialMember& m : members) {
    out.push_back(fit_internal::InvalidResult(IsCone(m) ? Surface(Cone{}) : Surface(Cylinder{})));
  }
  return out;
}

}  // namespace

std::vector<FitResult> FitCoaxial(std::span<const CoaxialMember> members,
                                  const Eigen::Vector3d& axis_origin,
                                  const Eigen::Vector3d& axis_direction, const FitParams& params) {
  const Eigen::Vector3d a = axis_direction.normalized();
  if (members.empty() || !axis_origin.allFinite() || !a.allFinite()) return AllInvalid(members);
  for (const CoaxialMember& m : members) {
    const std::size_t least = IsCone(m) ? 6 : 5;
    if (m.type != SurfaceType::kCylinder && !IsCone(m)) return AllInvalid(members);
    if (m.input.points.size() < least) return AllInvalid(members);
  }
  Eigen::VectorXd x0(6 + 2 * members.size());
  x0.head<3>() = axis_origin;
  x0.segment<3>(3) = a;
  for (std::size_t j = 0; j < members.size(); ++j) {
    StartMember(members[j], axis_origin, a, &x0(6 + 2 * j), &x0(7 + 2 * j));
  }
  const CoaxialProblem problem(members);
  const fit_internal::LmOutcome lm = params.refine ? MinimizeLevenbergMarquardt(problem, x0, params)
                                                   : fit_internal::LmOutcome{.x = x0};
  const Eigen::Vector3d o = lm.x.head<3>();
  const Eigen::Vector3d axis = lm.x.segment<3>(3).normalized();
  std::vector<FitResult> out;
  for (std::size_t j = 0; j < members.size(); ++j) {
    FitResult r;
    if (!MemberSurface(members[j], o, axis, lm.x(6 + 2 * j), lm.x(7 + 2 * j), &r.surface)) {
      return AllInvalid(members);
    }
    r.valid = true;
    r.iterations = lm.iterations;
    fit_internal::SetDistanceErrors(members[j].input, &r);
    out.push_back(r);
  }
  return out;
}

}  // namespace meshseg
