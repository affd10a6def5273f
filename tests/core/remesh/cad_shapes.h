// CAD-style tessellations for the remesh and pipeline tests: few, long, thin
// triangles whose vertices lie exactly on the analytic surface, as a CAD
// exporter writes them.
#ifndef MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_
#define MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Core>

namespace meshseg::testing {

struct CadShape {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  // Which true surface each triangle lies on: 0 = cylinder side,
  // 1 = bottom cap (z = 0), 2 = top cap (z = height).
  std::vector<int> surface;
};

// A closed cylinder of `radius` and `height` along +z from the origin: the
// side as `segments` strips of two triangles spanning the full height, each
// cap as a fan from its centre (outward orientation).
inline CadShape CadCylinder(double radius, double height, int segments) {
  CadShape s;
  for (int k = 0; k < segments; ++k) {
    const double t = 2.0 * std::numbers::pi * k / segments;
    s.vertices.emplace_back(radius * std::cos(t), radius * std::sin(t), 0.0);
    s.vertices.emplace_back(radius * std::cos(t), radius * std::sin(t), height);
  }
  const int bottom = static_cast<int>(s.vertices.size());
  s.vertices.emplace_back(0.0, 0.0, 0.0);
  s.vertices.emplace_back(0.0, 0.0, height);
  const int top = bottom + 1;
  for (int k = 0; k < segments; ++k) {
    const int a = 2 * k, b = 2 * ((k + 1) % segments);  // bottom ring; +1 = top ring
    s.triangles.push_back({a, b, b + 1});
    s.triangles.push_back({a, b + 1, a + 1});
    s.surface.insert(s.surface.end(), {0, 0});
  }
  for (int k = 0; k < segments; ++k) {
    const int a = 2 * k, b = 2 * ((k + 1) % segments);
    s.triangles.push_back({bottom, b, a});
    s.surface.push_back(1);
    s.triangles.push_back({top, a + 1, b + 1});
    s.surface.push_back(2);
  }
  return s;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_
