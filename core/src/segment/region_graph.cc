#include "segment/region_graph.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Geometry>

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool TypesCompatible(SurfaceType x, SurfaceType y) {
  return x == y || x == SurfaceType::kQuadric || y == SurfaceType::kQuadric;
}

}  // namespace

std::vector<RegionArc> BuildRegionGraph(const SegmentContext& c, const std::vector<int>& labels,
                                        const std::vector<RegionState>& regions) {
  // Sum of normals of the boundary vertices of `from` next to `to`, each
  // vertex once per neighbouring region.
  std::map<std::pair<int, int>, Eigen::Vector3d> strip;
  std::vector<int> seen;
  for (int v = 0; v < c.vertex_count(); ++v) {
    const int a = labels[v];
    if (a < 0) continue;
    seen.clear();
    for (const int j : c.graph.Neighbors(v)) {
      const int b = labels[j];
      if (b < 0 || b == a || std::find(seen.begin(), seen.end(), b) != seen.end()) continue;
      seen.push_back(b);
      auto [it, inserted] = strip.try_emplace({a, b}, Eigen::Vector3d::Zero());
      it->second += c.normal(v);
    }
  }
  std::vector<RegionArc> arcs;
  for (const auto& [key, sum_ab] : strip) {
    const auto [a, b] = key;
    if (a > b) continue;
    const auto other = strip.find({b, a});
    if (other == strip.end()) continue;
    RegionArc arc{.a = a, .b = b};
    const double na = sum_ab.norm();
    const double nb = other->second.norm();
    const double cosine = na > 0.0 && nb > 0.0 ? sum_ab.dot(other->second) / (na * nb) : -1.0;
    arc.angle_deg = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / kPi;
    arc.smooth = arc.angle_deg < kSharpBoundaryDeg;
    arc.kept = arc.smooth && TypesCompatible(regions[a].type, regions[b].type);
    arcs.push_back(arc);
  }
  return arcs;
}

}  // namespace meshseg::segment_internal
