// SmallRadiusEdges(): r ≈ w / θ across every smooth edge of a tessellation.
#include "small_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace meshseg::remesh_internal {

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
    // a != b here: the faces' normals are not zero.
    const auto line = Eigen::ParametrizedLine<double, 3>::Through(a, b);
    const double width = std::max(line.distance(c0), line.distance(c1));
    const double radius = width / angle;
    if (radius < max_radius) edges.push_back({a, b, radius});
  }
  return edges;
}

}  // namespace meshseg::remesh_internal
