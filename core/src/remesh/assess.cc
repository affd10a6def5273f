// Assess(): tells CAD tessellations (long thin triangles) from scan-like
// meshes and picks the edge length to remesh them at.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "meshseg/remesh.h"

namespace meshseg {

TessellationShape Assess(const Mesh& mesh, const RemeshParams& params) {
  TessellationShape shape;
  const TriMesh& tri = mesh.tri;
  std::vector<double> shortest;
  shortest.reserve(tri.n_faces());
  double thin_area = 0.0;
  for (const auto f : tri.faces()) {
    auto fv = tri.cfv_iter(f);
    const Eigen::Vector3d a = ToEigen(tri.point(*fv));
    const Eigen::Vector3d b = ToEigen(tri.point(*++fv));
    const Eigen::Vector3d c = ToEigen(tri.point(*++fv));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double e0 = (b - a).norm(), e1 = (c - b).norm(), e2 = (a - c).norm();
    const double longest = std::max({e0, e1, e2});
    shape.surface_area += area;
    if (area <= 0.0) continue;
    shortest.push_back(std::min({e0, e1, e2}));
    // Height over the longest edge is 2 area / longest.
    if (longest * longest > kThinAspect * 2.0 * area) thin_area += area;
  }
  if (shortest.empty() || shape.surface_area <= 0.0) return shape;
  shape.thin_area_fraction = thin_area / shape.surface_area;
  auto mid = shortest.begin() + static_cast<std::ptrdiff_t>(shortest.size() / 2);
  std::nth_element(shortest.begin(), mid, shortest.end());
  shape.median_shortest_edge = *mid;
  // An equilateral triangle of side L has area sqrt(3)/4 L^2.
  const double min_length =
      std::sqrt(4.0 * shape.surface_area / (std::sqrt(3.0) * static_cast<double>(params.max_faces)));
  shape.target_edge_length = std::max(shape.median_shortest_edge, min_length);
  shape.cad_like = shape.thin_area_fraction > params.thin_area_fraction;
  shape.too_fine_to_remesh =
      shape.cad_like &&
      shape.target_edge_length > kMaxRemeshCoarsening * shape.median_shortest_edge;
  return shape;
}

}  // namespace meshseg
