#include "features/fillets.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace meshseg::features_internal {
namespace {

template <typename T>
const T* As(std::span<const Region> regions, int r) {
  return std::get_if<T>(&regions[r].surface);
}

// FLT1 / FLT2 for torus region t.
std::optional<Feature> TorusFillet(int t, const Torus& torus, const Topology& topology,
                                   std::span<const Region> regions, const RegionGraph& graph,
                                   const Tolerances& tol) {
  const AxisLine axis{torus.center, torus.axis_direction.normalized()};
  std::optional<int> plane;
  std::optional<int> sphere;
  std::optional<int> cylinder;
  for (const int n : graph.Neighbors(t)) {
    if (!graph.TangentBetween(t, n)) continue;
    if (const Plane* p = As<Plane>(regions, n); p && !plane && Parallel(p->normal, axis.direction, tol)) {
      plane = n;
    }
    if (const Sphere* s = As<Sphere>(regions, n);
        s && !sphere && DistanceToLine(s->center, axis) <= tol.distance) {
      sphere = n;
    }
    if (const Cylinder* c = As<Cylinder>(regions, n);
        c && !cylinder && SameAxis(*AxisOf(*c), axis, tol)) {
      cylinder = n;
    }
  }
  if (!plane || (!sphere && !cylinder)) return std::nullopt;
  Feature f;
  f.type = cylinder ? FeatureType::kFilletTorusCylinderPlane : FeatureType::kFilletTorusSpherePlane;
  f.regions = {t, cylinder ? *cylinder : *sphere, *plane};
  f.radius = torus.minor_radius;
  f.convex = topology.regions[t].normal_sign > 0;
  f.direction = axis.direction;
  f.point = axis.point;
  return f;
}

// FLT3 for cylinder region c.
std::optional<Feature> CylinderFillet(int c, const Cylinder& cylinder, const Topology& topology,
                                      std::span<const Region> regions, const RegionGraph& graph,
                                      const Tolerances& tol) {
  const AxisLine axis = *AxisOf(cylinder);
  std::vector<int> planes;
  for (const int n : graph.Neighbors(c)) {
    const Plane* p = As<Plane>(regions, n);
    if (p && graph.TangentBetween(c, n) && Perpendicular(p->normal, axis.direction, tol)) {
      planes.push_back(n);
    }
  }
  const double min_deg = tol.angle_rad * 180.0 / std::numbers::pi;
  for (size_t i = 0; i < planes.size(); ++i) {
    for (size_t j = i + 1; j < planes.size(); ++j) {
      const Eigen::Vector3d n1 =
          OutwardNormal(*As<Plane>(regions, planes[i]), topology.regions[planes[i]]);
      const Eigen::Vector3d n2 =
          OutwardNormal(*As<Plane>(regions, planes[j]), topology.regions[planes[j]]);
      const double opening =
          std::acos(std::clamp(n1.dot(n2), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      if (opening <= min_deg || opening >= 180.0 - min_deg) continue;
      Feature f;
      f.type = FeatureType::kFilletCylinderPlanes;
      f.regions = {c, planes[i], planes[j]};
      f.radius = cylinder.radius;
      f.convex = topology.regions[c].normal_sign > 0;
      f.opening_angle_deg = opening;
      f.direction = axis.direction;
      f.point = axis.point;
      return f;
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<Feature> FindEdgeFillets(const Topology& topology, std::span<const Region> regions,
                                     const RegionGraph& graph, const Tolerances& tol) {
  std::vector<Feature> out;
  for (int r = 0; r < static_cast<int>(regions.size()); ++r) {
    std::optional<Feature> f;
    if (const Torus* t = As<Torus>(regions, r)) f = TorusFillet(r, *t, topology, regions, graph, tol);
    if (const Cylinder* c = As<Cylinder>(regions, r)) {
      f = CylinderFillet(r, *c, topology, regions, graph, tol);
    }
    if (f) out.push_back(std::move(*f));
  }
  return out;
}

std::vector<Feature> FindCornerBlends(const Topology& topology, std::span<const Region> regions,
                                      const RegionGraph& graph,
                                      std::span<const Feature> fillets) {
  std::map<int, bool> flt3_convex;  // FLT3 blend region -> convex
  for (const Feature& f : fillets) {
    if (f.type == FeatureType::kFilletCylinderPlanes) flt3_convex[f.regions[0]] = f.convex;
  }
  std::vector<Feature> out;
  for (int r = 0; r < static_cast<int>(regions.size()); ++r) {
    const Sphere* sphere = As<Sphere>(regions, r);
    const Torus* torus = As<Torus>(regions, r);
    if (!sphere && !torus) continue;
    std::vector<int> joined;
    for (const int n : graph.Neighbors(r)) {
      if (flt3_convex.count(n) && graph.TangentBetween(r, n)) joined.push_back(n);
    }
    if (joined.size() < 3) continue;
    joined.resize(3);
    const int convex_count = static_cast<int>(flt3_convex[joined[0]]) +
                             static_cast<int>(flt3_convex[joined[1]]) +
                             static_cast<int>(flt3_convex[joined[2]]);
    const bool uniform = convex_count == 0 || convex_count == 3;
    // FLT4 is a sphere exactly when the three fillets agree (seed 002 D1).
    if (uniform != (sphere != nullptr)) continue;
    Feature f;
    f.type = uniform ? FeatureType::kCornerBlendSphere : FeatureType::kCornerBlendTorus;
    f.regions = {r, joined[0], joined[1], joined[2]};
    f.radius = sphere ? sphere->radius : torus->minor_radius;
    f.convex = topology.regions[r].normal_sign > 0;
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace meshseg::features_internal
