// CAD-style tessellations for the remesh and pipeline tests: few, long, thin
// triangles whose vertices lie exactly on the analytic surface, as a CAD
// exporter writes them.
#ifndef MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_
#define MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"

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

// A square plate [-half_width, half_width]^2 x [0, thickness] with a round
// hole of `radius` through its centre, the hole's wall as `segments` strips
// (a multiple of 4) spanning the thickness and each face of the plate as
// quads from the hole out to the edge, split in two: the long slivers of a
// CAD export. surface: 0 = hole wall, 1 = bottom, 2 = top, 3 = outer sides.
inline CadShape CadPlateWithHole(double half_width, double thickness, double radius,
                                 int segments) {
  CadShape s;
  // Per segment k: hole bottom 4k, hole top 4k+1, edge bottom 4k+2, edge top
  // 4k+3. The rays start at 45 degrees so that the plate's corners are on them.
  for (int k = 0; k < segments; ++k) {
    const double t = std::numbers::pi / 4.0 + 2.0 * std::numbers::pi * k / segments;
    const double c = std::cos(t), n = std::sin(t);
    const double to_edge = half_width / std::max(std::abs(c), std::abs(n));
    for (const double z : {0.0, thickness}) s.vertices.emplace_back(radius * c, radius * n, z);
    for (const double z : {0.0, thickness}) s.vertices.emplace_back(to_edge * c, to_edge * n, z);
  }
  const auto quad = [&s](int a, int b, int c, int d, int surface) {  // a b c d counterclockwise
    s.triangles.push_back({a, b, c});
    s.triangles.push_back({a, c, d});
    s.surface.insert(s.surface.end(), {surface, surface});
  };
  for (int k = 0; k < segments; ++k) {
    const int a = 4 * k, b = 4 * ((k + 1) % segments);
    quad(a, a + 1, b + 1, b, 0);          // wall, facing the hole's axis
    quad(a, b, b + 2, a + 2, 1);          // bottom, facing -z
    quad(a + 1, a + 3, b + 3, b + 1, 2);  // top, facing +z
    quad(a + 2, b + 2, b + 3, a + 3, 3);  // outer side, facing out
  }
  return s;
}

// The shape as a Mesh named `name` (a test failure if it does not build).
inline Mesh MeshOf(const CadShape& shape, const std::string& name = "cad_shape") {
  absl::StatusOr<Mesh> mesh = BuildMesh(shape.vertices, shape.triangles, name);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return mesh.ok() ? *std::move(mesh) : Mesh{};
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_REMESH_CAD_SHAPES_H_
