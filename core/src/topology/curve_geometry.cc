#include "topology/curve_geometry.h"

#include <optional>

#include <Eigen/Geometry>

#include "topology/fit_curve.h"

namespace meshseg::topology_internal {
namespace {

// Points lines along the curve and circle normals so the curve turns
// counterclockwise about them.
void Orient(std::span<const Eigen::Vector3d> points, CurveGeometry* g) {
  double sense = 0.0;
  if (g->type == CurveGeometryType::kLine) {
    sense = (points.back() - points.front()).dot(g->direction);
  } else if (g->type == CurveGeometryType::kCircle) {
    for (size_t i = 0; i + 1 < points.size(); ++i) {
      sense += (points[i] - g->point).cross(points[i + 1] - g->point).dot(g->direction);
    }
  }
  if (sense < 0.0) g->direction = -g->direction;
}

// `g` with its deviation if within `tolerance`.
std::optional<CurveGeometry> Accept(std::optional<CurveGeometry> g,
                                    std::span<const Eigen::Vector3d> points, double tolerance) {
  if (!g) return std::nullopt;
  g->max_deviation = MaxDeviation(*g, points);
  if (g->max_deviation > tolerance) return std::nullopt;
  Orient(points, &*g);
  return g;
}

}  // namespace

CurveGeometry CurveGeometryOf(std::span<const Eigen::Vector3d> points, const Surface* left,
                              const Surface* right, const IntersectionTolerances& tol) {
  if (left != nullptr && right != nullptr) {
    if (auto g = Accept(IntersectSurfaces(*left, *right, points, tol), points, tol.distance)) {
      return *g;
    }
  }
  if (auto g = Accept(FitLine(points), points, tol.distance)) return *g;
  if (auto g = Accept(FitCircle(points), points, tol.distance)) return *g;
  return CurveGeometry{};
}

}  // namespace meshseg::topology_internal
