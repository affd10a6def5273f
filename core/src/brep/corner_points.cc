#include "brep/corner_points.h"

#include <algorithm>
#include <optional>

#include <Eigen/Dense>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

constexpr int kMaxIterations = 20;
// The least weight of the pull towards the start relative to a unit-normal
// row: it only makes the directions nothing constrains well posed.
constexpr double kLeastPull = 1e-10;

// The Gauss-Newton step for the normal equations `jtj` x = -`jtr`, solved
// exactly along the eigendirections the rows fix (eigenvalue >= `resolved`)
// and pulled back towards the start (`offset` = x - start) with weight
// `resolved` along the others.
Eigen::Vector3d Step(const Eigen::Matrix3d& jtj, const Eigen::Vector3d& jtr,
                     const Eigen::Vector3d& offset, double resolved) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(jtj);
  Eigen::Vector3d step = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = eigen.eigenvectors().col(i);
    const double lambda = std::max(eigen.eigenvalues()(i), 0.0);
    const double g = e.dot(jtr);
    step -=
        (lambda >= resolved ? g / lambda : (g + resolved * e.dot(offset)) / (lambda + resolved)) *
        e;
  }
  return step;
}

// A direction fixes the corner when moving the corner by `spacing` along it
// changes the rows' distances by more than `surface_offset`: the rows'
// eigenvalue along it exceeds (surface_offset / spacing)^2.
double Resolved(const CornerNoise& noise) {
  const double r = noise.spacing > 0.0 ? noise.surface_offset / noise.spacing : 0.0;
  return std::max(r * r, kLeastPull);
}

// The normal equations of the distances at a point: rows = how many
// constraints were found there.
struct NormalEquations {
  Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
  Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
  int rows = 0;
};

// Gauss-Newton from `start` on the equations `at` gives at each point,
// solved by Step; `start` when no row constrains or the iteration leaves
// the ball of radius `max_move`.
template <typename At>
Eigen::Vector3d Solve(const Eigen::Vector3d& start, double max_move, const CornerNoise& noise,
                      At at) {
  const double resolved = Resolved(noise);
  Eigen::Vector3d x = start;
  for (int it = 0; it < kMaxIterations; ++it) {
    const NormalEquations e = at(x);
    if (e.rows == 0) return start;
    const Eigen::Vector3d step = Step(e.jtj, e.jtr, x - start, resolved);
    x += step;
    if ((x - start).norm() > max_move) return start;
    if (step.norm() < 1e-12 * (1.0 + max_move)) break;
  }
  return x;
}

}  // namespace

Eigen::Vector3d CornerPoint(const Eigen::Vector3d& start,
                            std::span<const Handle(Geom_Surface)> surfaces, double max_move,
                            const CornerNoise& noise) {
  return Solve(start, max_move, noise, [&](const Eigen::Vector3d& x) {
    NormalEquations e;
    for (const Handle(Geom_Surface) & s : surfaces) {
      if (s.IsNull()) continue;
      const std::optional<SurfacePoint> q = ClosestPoint(s, x);
      if (!q) continue;
      e.jtj += q->normal * q->normal.transpose();
      e.jtr += q->normal * q->distance;
      ++e.rows;
    }
    return e;
  });
}

Eigen::Vector3d CornerOnCurves(const Eigen::Vector3d& start,
                               std::span<const Handle(Geom_Curve)> curves, double max_move,
                               const CornerNoise& noise) {
  return Solve(start, max_move, noise, [&](const Eigen::Vector3d& x) {
    // Each curve constrains the two directions across its tangent.
    NormalEquations e;
    for (const Handle(Geom_Curve) & c : curves) {
      const double t = ClosestParameter(c, x, c->FirstParameter(), c->LastParameter());
      gp_Pnt p;
      gp_Vec d;
      c->D1(t, p, d);
      const Eigen::Vector3d tangent = ToEigen(d).normalized();
      const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - tangent * tangent.transpose();
      e.jtj += across;
      e.jtr += across * (x - ToEigen(p));
      ++e.rows;
    }
    return e;
  });
}

}  // namespace meshseg::brep_internal
