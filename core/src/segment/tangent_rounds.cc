#include "segment/tangent_rounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Geometry>

#include "segment/align_coaxial.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

double Radians(double deg) { return deg * std::numbers::pi / 180.0; }

// +1 if `p` lies on the side of `plane` its normal points to, else -1.
int SideOf(const Plane& plane, const Eigen::Vector3d& p) {
  return (p - plane.point).dot(plane.normal) >= 0.0 ? 1 : -1;
}

// The planes around region `id` whose normals are within
// kCoaxialMaxAngleDeg of square to `axis`.
std::vector<const Plane*> PlanesAlong(const SegmentContext& c, const std::vector<int>& labels,
                                      const std::vector<RegionState>& regions, int id,
                                      const Eigen::Vector3d& axis) {
  const double sin_max = std::sin(Radians(kCoaxialMaxAngleDeg));
  std::vector<const Plane*> planes;
  for (const int n : RegionsAround(c, labels, regions, id)) {
    const auto* plane = std::get_if<Plane>(&regions[n].surface);
    if (regions[n].alive && regions[n].type == SurfaceType::kPlane && plane != nullptr &&
        std::abs(plane->normal.normalized().dot(axis)) <= sin_max) {
      planes.push_back(plane);
    }
  }
  return planes;
}

// The tangent fit to `input` with the least error over the pairs of
// `planes` at least kMinRoundAngleDeg apart.
std::optional<FitResult> BestTangentFit(const FitInput& input, const Cylinder& own,
                                        const std::vector<const Plane*>& planes) {
  const double sin_min = std::sin(Radians(kMinRoundAngleDeg));
  std::optional<FitResult> best;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      const Plane& a = *planes[i];
      const Plane& b = *planes[j];
      if (a.normal.normalized().cross(b.normal.normalized()).norm() < sin_min) continue;
      const std::array<int, 2> sides = {SideOf(a, own.axis_origin), SideOf(b, own.axis_origin)};
      FitResult fit = FitCylinderTangentToPlanes(input, a, b, sides, own.radius);
      if (fit.ok() && (!best || fit.rms_distance < best->rms_distance)) best = std::move(fit);
    }
  }
  return best;
}

}  // namespace

std::vector<int> FitRoundsTangentToPlanes(const SegmentContext& c, const std::vector<int>& labels,
                                          std::vector<RegionState>* regions) {
  std::vector<int> changed;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    const auto* own = std::get_if<Cylinder>(&r.surface);
    if (!r.alive || r.type != SurfaceType::kCylinder || own == nullptr) continue;
    const std::vector<const Plane*> planes =
        PlanesAlong(c, labels, *regions, id, own->axis_direction.normalized());
    if (planes.size() < 2) continue;
    std::vector<Eigen::Vector3d> points, normals;
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
    for (const int v : Sample(MeasuredVertices(c, FittingVertices(c, r.surface, interior)))) {
      points.push_back(c.position(v));
      normals.push_back(c.normal(v));
    }
    if (points.size() < 6) continue;
    const FitResult free = FitCylinder({.points = points, .normals = normals, .weights = {}});
    const std::optional<FitResult> tangent =
        BestTangentFit({.points = points, .normals = {}, .weights = {}}, *own, planes);
    if (!free.ok() || !tangent) continue;
    const double m = static_cast<double>(points.size());
    const double free_cost = std::pow(free.rms_distance, 2) * m;
    const double variance = ResidualVariance(c, free_cost, m, 5.0);
    const double rise = std::pow(tangent->rms_distance, 2) * m - free_cost;
    if (!(rise <= kCoaxialChiSquare * variance)) continue;
    r.surface = tangent->surface;
    changed.push_back(id);
  }
  return changed;
}

}  // namespace meshseg::segment_internal
