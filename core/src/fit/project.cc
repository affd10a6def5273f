// Closest point, normal there and signed distance for the analytic surfaces
// (closed forms); the quadric's iterative projection is in project_quadric.cc.
// Every branch returns finite numbers, also for points on an axis or at an apex.
#include <cmath>
#include <type_traits>
#include <variant>

#include "fit/fit_internal.h"
#include "fit/project_quadric.h"
#include "meshseg/fit.h"

namespace meshseg {
namespace {

using fit_internal::AnyPerpendicular;

// Unit vector of `v`, or of `fallback` projected off `axis` (then any
// perpendicular) when v is too short to have a direction.
Eigen::Vector3d RadialDirection(const Eigen::Vector3d& v, const Eigen::Vector3d& axis,
                                const Eigen::Vector3d& fallback) {
  const double n = v.norm();
  if (n > 1e-300 && std::isfinite(n)) return v / n;
  const Eigen::Vector3d f = fallback - fallback.dot(axis) * axis;
  const double fn = f.norm();
  if (fn > 1e-12) return f / fn;
  return AnyPerpendicular(axis);
}

Eigen::Vector3d Unit(const Eigen::Vector3d& v) {
  const double n = v.norm();
  return n > 0.0 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::UnitZ();
}

Projection ProjectPlane(const Plane& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d n = Unit(s.normal);
  const double d = (p - s.point).dot(n);
  return {p - d * n, n, d};
}

Projection ProjectSphere(const Sphere& s, const Eigen::Vector3d& p, const Eigen::Vector3d& hint) {
  const Eigen::Vector3d v = p - s.center;
  Eigen::Vector3d n;
  const double len = v.norm();
  if (len > 1e-300) {
    n = v / len;
  } else {
    n = hint.norm() > 0.0 ? Unit(hint) : Eigen::Vector3d::UnitZ();
  }
  return {s.center + s.radius * n, n, len - s.radius};
}

Projection ProjectCylinder(const Cylinder& s, const Eigen::Vector3d& p,
                          const Eigen::Vector3d& hint) {
  const Eigen::Vector3d a = Unit(s.axis_direction);
  const Eigen::Vector3d v = p - s.axis_origin;
  const double t = v.dot(a);
  const Eigen::Vector3d radial = v - t * a;
  const Eigen::Vector3d e = RadialDirection(radial, a, hint);
  return {s.axis_origin + t * a + s.radius * e, e, radial.norm() - s.radius};
}

// In the half-plane through the axis and p, with axial coordinate h and
// radial coordinate rho >= 0, the cone is the half-line from the apex along
// (sin α, cos α); its outward normal is (cos α, -sin α).
Projection ProjectCone(const Cone& s, const Eigen::Vector3d& p, const Eigen::Vector3d& hint) {
  const Eigen::Vector3d a = Unit(s.axis_direction);
  const Eigen::Vector3d v = p - s.apex;
  const double h = v.dot(a);
  const Eigen::Vector3d radial = v - h * a;
  const double rho = radial.norm();
  const Eigen::Vector3d e = RadialDirection(radial, a, hint);
  const double sin_a = std::sin(s.half_angle);
  const double cos_a = std::cos(s.half_angle);
  const Eigen::Vector3d normal = cos_a * e - sin_a * a;
  const double line_distance = rho * cos_a - h * sin_a;
  const double along = rho * sin_a + h * cos_a;  // position along the generator
  if (along >= 0.0) {
    const Eigen::Vector3d foot = s.apex + along * (sin_a * e + cos_a * a);
    return {foot, normal, line_distance};
  }
  // Behind the apex: the apex is the closest point.
  const double dist = v.norm();
  return {s.apex, normal, line_distance >= 0.0 ? dist : -dist};
}

Projection ProjectTorus(const Torus& s, const Eigen::Vector3d& p, const Eigen::Vector3d& hint) {
  const Eigen::Vector3d a = Unit(s.axis_direction);
  const Eigen::Vector3d v = p - s.center;
  const double h = v.dot(a);
  const Eigen::Vector3d e = RadialDirection(v - h * a, a, hint);
  const Eigen::Vector3d tube_center = s.center + s.major_radius * e;
  const Eigen::Vector3d w = p - tube_center;
  const double len = w.norm();
  const Eigen::Vector3d n = len > 1e-300 ? Eigen::Vector3d(w / len) : e;
  return {tube_center + s.minor_radius * n, n, len - s.minor_radius};
}

}  // namespace

Projection Project(const Surface& surface, const Eigen::Vector3d& p,
                   const Eigen::Vector3d& hint_direction) {
  return std::visit(
      [&](const auto& s) -> Projection {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) return ProjectPlane(s, p);
        if constexpr (std::is_same_v<T, Sphere>) return ProjectSphere(s, p, hint_direction);
        if constexpr (std::is_same_v<T, Cylinder>) return ProjectCylinder(s, p, hint_direction);
        if constexpr (std::is_same_v<T, Cone>) return ProjectCone(s, p, hint_direction);
        if constexpr (std::is_same_v<T, Torus>) return ProjectTorus(s, p, hint_direction);
        if constexpr (std::is_same_v<T, Quadric>) {
          return fit_internal::ProjectQuadric(s, p, hint_direction);
        }
      },
      surface);
}

double SignedDistance(const Surface& surface, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& hint_direction) {
  return SurfaceDistance(surface)(p, hint_direction);
}

SurfaceDistance::SurfaceDistance(const Surface& surface) : surface_(surface) {
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) unit_ = Unit(s.normal);
        if constexpr (std::is_same_v<T, Cylinder> || std::is_same_v<T, Cone> ||
                      std::is_same_v<T, Torus>) {
          unit_ = Unit(s.axis_direction);
        }
        if constexpr (std::is_same_v<T, Cone>) {
          sin_angle_ = std::sin(s.half_angle);
          cos_angle_ = std::cos(s.half_angle);
        }
      },
      surface_);
}

// Each distance below is computed by the same expressions, in the same
// order, as the Project* function above of its type (with unit_ their
// a = Unit(axis) or n = Unit(normal)), so it is the same double; only what
// the distance does not depend on is left out.
double SurfaceDistance::operator()(const Eigen::Vector3d& p,
                                   const Eigen::Vector3d& hint_direction) const {
  return std::visit(
      [&](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) return (p - s.point).dot(unit_);
        if constexpr (std::is_same_v<T, Sphere>) return (p - s.center).norm() - s.radius;
        if constexpr (std::is_same_v<T, Cylinder>) {
          const Eigen::Vector3d v = p - s.axis_origin;
          const double t = v.dot(unit_);
          const Eigen::Vector3d radial = v - t * unit_;
          return radial.norm() - s.radius;
        }
        if constexpr (std::is_same_v<T, Cone>) {
          const Eigen::Vector3d v = p - s.apex;
          const double h = v.dot(unit_);
          const Eigen::Vector3d radial = v - h * unit_;
          const double rho = radial.norm();
          const double line_distance = rho * cos_angle_ - h * sin_angle_;
          if (rho * sin_angle_ + h * cos_angle_ >= 0.0) return line_distance;
          const double dist = v.norm();
          return line_distance >= 0.0 ? dist : -dist;
        }
        if constexpr (std::is_same_v<T, Torus>) {
          const Eigen::Vector3d v = p - s.center;
          const double h = v.dot(unit_);
          const Eigen::Vector3d e = RadialDirection(v - h * unit_, unit_, hint_direction);
          const Eigen::Vector3d tube_center = s.center + s.major_radius * e;
          return (p - tube_center).norm() - s.minor_radius;
        }
        if constexpr (std::is_same_v<T, Quadric>) {
          return fit_internal::ProjectQuadric(s, p, hint_direction).distance;
        }
      },
      surface_);
}

}  // namespace meshseg
