// SmallRadiusEdges(): r ≈ w / θ across every smooth edge of a tessellation.
#include "small_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace meshseg::remesh_internal {
namespace {

// Height of `p` over the line through a and b.
double HeightOverLine(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                      const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length = ab.norm();
  if (length <= 0.0) return 0.0;
  return ab.cross(p - a).norm() / length;
}

}  // namespace

std::vector<CurvedEdge> SmallRadiusEdges(const TriMesh& tri, double max_radius,
                                         double feature_angle_deg) {
  std::vector<CurvedEdge> edges;
  const double max_angle = feature_angle_deg * std::numbers::pi / 180.0;
  for (const auto e : tri.edges()) {
    if (tri.is_boundary(e)) continue;
    const auto h0 = tri.halfedge_handle(e, 0), h1 = tri.halfedge_handle(e, 1);
    const Eigen::Vector3d a = ToEigen(tri.point(tri.from_vertex_handle(h0)));
    const Eigen::Vector3d b = ToEigen(tri.point(tri.to_vertex_handle(h0)));
    const Eigen::Vector3d c0 = ToEigen(tri.point(tri.to_vertex_handle(tri.next_halfedge_handle(h0))));
    const Eigen::Vector3d c1 = ToEigen(tri.point(tri.to_vertex_handle(tri.next_halfedge_handle(h1))));
    const Eigen::Vector3d n0 = (b - a).cross(c0 - a), n1 = (a - b).cross(c1 - b);
    if (n0.norm() <= 0.0 || n1.norm() <= 0.0) continue;
    const double angle = std::atan2(n0.cross(n1).norm(), n0.dot(n1));
    if (!(angle > 0.0) || angle >= max_angle) continue;
    const double width = std::max(HeightOverLine(c0, a, b), HeightOverLine(c1, a, b));
    const double radius = width / angle;
    if (radius < max_radius) edges.push_back({a, b, radius});
  }
  return edges;
}

}  // namespace meshseg::remesh_internal
