#include "topology/profile_intersection.h"

#include <cmath>

namespace meshseg::topology_internal {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

const Eigen::Vector2d& Nearer(const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                              const Eigen::Vector2d& near) {
  return (p - near).squaredNorm() <= (q - near).squaredNorm() ? p : q;
}

std::optional<Eigen::Vector2d> LineLine(const Profile& a, const Profile& b) {
  const double denom = Cross(a.direction, b.direction);
  if (std::abs(denom) < 1e-9) return std::nullopt;
  const double t = Cross(b.point - a.point, b.direction) / denom;
  return Eigen::Vector2d(a.point + t * a.direction);
}

std::optional<Eigen::Vector2d> LineCircle(const Profile& line, const Profile& circle,
                                          const Eigen::Vector2d& near, double tol) {
  const Eigen::Vector2d foot =
      line.point + (circle.point - line.point).dot(line.direction) * line.direction;
  const Eigen::Vector2d to_foot = foot - circle.point;
  const double delta = to_foot.norm();
  if (delta <= circle.radius) {
    const double half = std::sqrt(circle.radius * circle.radius - delta * delta);
    return Nearer(foot + half * line.direction, foot - half * line.direction, near);
  }
  if (delta - circle.radius > tol) return std::nullopt;
  const Eigen::Vector2d on_circle = circle.point + circle.radius * to_foot / delta;
  return Eigen::Vector2d(0.5 * (on_circle + foot));
}

std::optional<Eigen::Vector2d> CircleCircle(const Profile& a, const Profile& b,
                                            const Eigen::Vector2d& near, double tol) {
  const Eigen::Vector2d between = b.point - a.point;
  const double d = between.norm();
  if (d < 1e-12) return std::nullopt;  // concentric: no isolated point
  const Eigen::Vector2d u = between / d;
  const double outer_gap = d - (a.radius + b.radius);          // > 0: apart
  const double inner_gap = std::abs(a.radius - b.radius) - d;  // > 0: nested
  if (outer_gap > 0.0 || inner_gap > 0.0) {
    if (std::max(outer_gap, inner_gap) > tol) return std::nullopt;
    // Tangent: midway between the closest points along the centre line.
    // Apart: facing sides. Nested: both on the side the inner one is offset to.
    const double nested_side = a.radius > b.radius ? 1.0 : -1.0;
    const double sign_a = outer_gap > 0.0 ? 1.0 : nested_side;
    const double sign_b = outer_gap > 0.0 ? -1.0 : nested_side;
    const Eigen::Vector2d pa = a.point + sign_a * a.radius * u;
    const Eigen::Vector2d pb = b.point + sign_b * b.radius * u;
    return Eigen::Vector2d(0.5 * (pa + pb));
  }
  const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2.0 * d);
  const double half = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  const Eigen::Vector2d mid = a.point + along * u;
  const Eigen::Vector2d perp(-u.y(), u.x());
  return Nearer(mid + half * perp, mid - half * perp, near);
}

}  // namespace

std::optional<Eigen::Vector2d> IntersectProfiles(const Profile& a, const Profile& b,
                                                 const Eigen::Vector2d& near,
                                                 double tangent_tolerance) {
  if (!a.is_circle && !b.is_circle) return LineLine(a, b);
  if (!a.is_circle) return LineCircle(a, b, near, tangent_tolerance);
  if (!b.is_circle) return LineCircle(b, a, near, tangent_tolerance);
  return CircleCircle(a, b, near, tangent_tolerance);
}

}  // namespace meshseg::topology_internal
