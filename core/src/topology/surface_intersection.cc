#include "topology/surface_intersection.h"

#include <cmath>
#include <type_traits>
#include <variant>

#include <Eigen/Geometry>

#include "topology/profile_intersection.h"

namespace meshseg::topology_internal {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// What a surface says about a rotation axis: a line (cylinder, cone, torus),
// a direction only (plane normal), a point only (sphere centre), or nothing.
struct AxisHint {
  enum Kind { kLine, kDirection, kPoint, kNone } kind = kNone;
  Vector3d point = Vector3d::Zero();
  Vector3d direction = Vector3d::UnitZ();
};

AxisHint HintOf(const Surface& s) {
  return std::visit(
      [](const auto& x) -> AxisHint {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Plane>) {
          return {AxisHint::kDirection, x.point, x.normal.normalized()};
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return {AxisHint::kLine, x.axis_origin, x.axis_direction.normalized()};
        } else if constexpr (std::is_same_v<T, Cone>) {
          return {AxisHint::kLine, x.apex, x.axis_direction.normalized()};
        } else if constexpr (std::is_same_v<T, Torus>) {
          return {AxisHint::kLine, x.center, x.axis_direction.normalized()};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return {AxisHint::kPoint, x.center, Vector3d::UnitZ()};
        } else {
          return {};
        }
      },
      s);
}

double LineDistance(const Vector3d& p, const Vector3d& o, const Vector3d& d) {
  const Vector3d v = p - o;
  return (v - v.dot(d) * d).norm();
}

// The axis both surfaces turn about, if they share one.
std::optional<AxisHint> CommonAxis(AxisHint a, AxisHint b, const IntersectionTolerances& tol) {
  const double cos_tol = std::cos(tol.angle_rad);
  if (a.kind > b.kind) std::swap(a, b);  // order: line, direction, point, none
  if (b.kind == AxisHint::kNone) return std::nullopt;
  if (a.kind == AxisHint::kLine) {
    const bool parallel = std::abs(a.direction.dot(b.direction)) >= cos_tol;
    if (b.kind == AxisHint::kLine && parallel &&
        LineDistance(b.point, a.point, a.direction) <= tol.distance) {
      return a;
    }
    if (b.kind == AxisHint::kDirection && parallel) return a;
    if (b.kind == AxisHint::kPoint && LineDistance(b.point, a.point, a.direction) <= tol.distance) {
      return a;
    }
    return std::nullopt;
  }
  if (a.kind == AxisHint::kDirection && b.kind == AxisHint::kPoint) {
    return AxisHint{AxisHint::kLine, b.point, a.direction};
  }
  if (a.kind == AxisHint::kPoint && b.kind == AxisHint::kPoint) {
    const Vector3d between = b.point - a.point;
    if (between.norm() <= tol.distance) return std::nullopt;
    return AxisHint{AxisHint::kLine, a.point, between.normalized()};
  }
  return std::nullopt;
}

// The profile of `s` in the half-plane (t, rho) about the axis (o, d).
std::optional<Profile> MeridianProfile(const Surface& s, const Vector3d& o, const Vector3d& d) {
  return std::visit(
      [&](const auto& x) -> std::optional<Profile> {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Plane>) {
          // Where the plane crosses the axis: a plane tilted (within the angle
          // tolerance) against the axis must not be measured at its far-off
          // reference point.
          const Vector3d n = x.normal.normalized();
          const double t0 = (x.point - o).dot(n) / d.dot(n);
          return Profile{false, Vector2d(t0, 0.0), Vector2d::UnitY(), 0.0};
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return Profile{false, Vector2d(0.0, x.radius), Vector2d::UnitX(), 0.0};
        } else if constexpr (std::is_same_v<T, Cone>) {
          const double side = x.axis_direction.dot(d) >= 0.0 ? 1.0 : -1.0;
          return Profile{false, Vector2d((x.apex - o).dot(d), 0.0),
                         Vector2d(side * std::cos(x.half_angle), std::sin(x.half_angle)), 0.0};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return Profile{true, Vector2d((x.center - o).dot(d), 0.0), Vector2d::UnitX(), x.radius};
        } else if constexpr (std::is_same_v<T, Torus>) {
          return Profile{true, Vector2d((x.center - o).dot(d), x.major_radius), Vector2d::UnitX(),
                         x.minor_radius};
        } else {
          return std::nullopt;
        }
      },
      s);
}

std::optional<CurveGeometry> CoaxialCircle(const Surface& a, const Surface& b,
                                           std::span<const Vector3d> points,
                                           const IntersectionTolerances& tol) {
  const std::optional<AxisHint> axis = CommonAxis(HintOf(a), HintOf(b), tol);
  if (!axis) return std::nullopt;
  const Vector3d& o = axis->point;
  const Vector3d& d = axis->direction;
  const std::optional<Profile> pa = MeridianProfile(a, o, d);
  const std::optional<Profile> pb = MeridianProfile(b, o, d);
  if (!pa || !pb) return std::nullopt;
  Vector2d near = Vector2d::Zero();
  for (const Vector3d& p : points) near += Vector2d((p - o).dot(d), LineDistance(p, o, d));
  near /= static_cast<double>(points.size());
  const std::optional<Vector2d> q = IntersectProfiles(*pa, *pb, near, tol.distance);
  if (!q || q->y() <= 0.0) return std::nullopt;
  CurveGeometry g;
  g.type = CurveGeometryType::kCircle;
  g.point = o + q->x() * d;
  g.direction = d;
  g.radius = q->y();
  g.analytic = true;
  return g;
}

// The direction both surfaces are extruded along, if any.
std::optional<Vector3d> CommonExtrusion(const AxisHint& a, const AxisHint& b,
                                        const IntersectionTolerances& tol) {
  const double sin_tol = std::sin(tol.angle_rad);
  const double dot = a.direction.dot(b.direction);
  if (a.kind == AxisHint::kDirection && b.kind == AxisHint::kDirection) {
    const Vector3d c = a.direction.cross(b.direction);
    if (c.norm() <= sin_tol) return std::nullopt;
    return Vector3d(c.normalized());
  }
  if (a.kind == AxisHint::kDirection && b.kind == AxisHint::kLine) {
    return std::abs(dot) <= sin_tol ? std::optional<Vector3d>(b.direction) : std::nullopt;
  }
  if (a.kind == AxisHint::kLine && b.kind == AxisHint::kDirection) {
    return std::abs(dot) <= sin_tol ? std::optional<Vector3d>(a.direction) : std::nullopt;
  }
  return std::nullopt;
}

// The cross-section of a plane or cylinder in the basis (e1, e2).
std::optional<Profile> CrossSection(const Surface& s, const Vector3d& e1, const Vector3d& e2) {
  if (const auto* p = std::get_if<Plane>(&s)) {
    const Vector2d n(p->normal.dot(e1), p->normal.dot(e2));
    if (n.norm() < 1e-12) return std::nullopt;
    return Profile{false, Vector2d(p->point.dot(e1), p->point.dot(e2)),
                   Vector2d(-n.y(), n.x()).normalized(), 0.0};
  }
  if (const auto* c = std::get_if<Cylinder>(&s)) {
    return Profile{true, Vector2d(c->axis_origin.dot(e1), c->axis_origin.dot(e2)),
                   Vector2d::UnitX(), c->radius};
  }
  return std::nullopt;
}

std::optional<CurveGeometry> ExtrusionLine(const Surface& a, const Surface& b,
                                           std::span<const Vector3d> points,
                                           const IntersectionTolerances& tol) {
  const std::optional<Vector3d> dir = CommonExtrusion(HintOf(a), HintOf(b), tol);
  if (!dir) return std::nullopt;
  const Vector3d e1 = dir->unitOrthogonal();
  const Vector3d e2 = dir->cross(e1);
  const std::optional<Profile> pa = CrossSection(a, e1, e2);
  const std::optional<Profile> pb = CrossSection(b, e1, e2);
  if (!pa || !pb) return std::nullopt;
  Vector3d centroid = Vector3d::Zero();
  for (const Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const Vector2d near(centroid.dot(e1), centroid.dot(e2));
  const std::optional<Vector2d> q = IntersectProfiles(*pa, *pb, near, tol.distance);
  if (!q) return std::nullopt;
  CurveGeometry g;
  g.type = CurveGeometryType::kLine;
  g.point = q->x() * e1 + q->y() * e2 + centroid.dot(*dir) * *dir;
  g.direction = *dir;
  g.analytic = true;
  return g;
}

}  // namespace

std::optional<CurveGeometry> IntersectSurfaces(const Surface& a, const Surface& b,
                                               std::span<const Vector3d> points,
                                               const IntersectionTolerances& tol) {
  if (points.empty()) return std::nullopt;
  if (auto circle = CoaxialCircle(a, b, points, tol)) return circle;
  return ExtrusionLine(a, b, points, tol);
}

}  // namespace meshseg::topology_internal
