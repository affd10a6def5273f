#include "brep/corner_points.h"

#include <optional>

#include <Eigen/Dense>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

constexpr int kMaxIterations = 20;
// Weight of the pull towards the start relative to a unit-normal row: small
// enough to leave the surfaces' common point where they cross transversally,
// large enough to make the free directions well posed.
constexpr double kPull = 1e-6;

}  // namespace

Eigen::Vector3d CornerPoint(const Eigen::Vector3d& start,
                            std::span<const Handle(Geom_Surface)> surfaces, double max_move) {
  Eigen::Vector3d x = start;
  for (int it = 0; it < kMaxIterations; ++it) {
    Eigen::Matrix3d jtj = kPull * Eigen::Matrix3d::Identity();
    Eigen::Vector3d jtr = kPull * (x - start);
    int rows = 0;
    for (const Handle(Geom_Surface) & s : surfaces) {
      if (s.IsNull()) continue;
      const std::optional<SurfacePoint> q = ClosestPoint(s, x);
      if (!q) continue;
      jtj += q->normal * q->normal.transpose();
      jtr += q->normal * q->distance;
      ++rows;
    }
    if (rows == 0) return start;
    const Eigen::Vector3d step = -jtj.ldlt().solve(jtr);
    x += step;
    if ((x - start).norm() > max_move) return start;
    if (step.norm() < 1e-12 * (1.0 + max_move)) break;
  }
  return x;
}

Eigen::Vector3d CornerOnCurves(const Eigen::Vector3d& start,
                               std::span<const Handle(Geom_Curve)> curves, double max_move) {
  Eigen::Vector3d x = start;
  for (int it = 0; it < kMaxIterations; ++it) {
    // Gauss-Newton on the distances to the curves: each curve constrains the
    // two directions across its tangent.
    Eigen::Matrix3d jtj = kPull * Eigen::Matrix3d::Identity();
    Eigen::Vector3d jtr = kPull * (x - start);
    for (const Handle(Geom_Curve) & c : curves) {
      const double t = ClosestParameter(c, x, c->FirstParameter(), c->LastParameter());
      gp_Pnt p;
      gp_Vec d;
      c->D1(t, p, d);
      const Eigen::Vector3d tangent = ToEigen(d).normalized();
      const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - tangent * tangent.transpose();
      jtj += across;
      jtr += across * (x - ToEigen(p));
    }
    const Eigen::Vector3d step = -jtj.ldlt().solve(jtr);
    x += step;
    if ((x - start).norm() > max_move) return start;
    if (step.norm() < 1e-12 * (1.0 + max_move)) break;
  }
  return x;
}

}  // namespace meshseg::brep_internal
