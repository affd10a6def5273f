#include "features/revolutions.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace meshseg::features_internal {
namespace {

// Axes of the axial regions, largest region first, coincident ones merged.
std::vector<AxisLine> CandidateAxes(std::span<const Region> regions, const Tolerances& tol) {
  std::vector<int> order(regions.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return regions[a].area > regions[b].area; });
  std::vector<AxisLine> out;
  for (const int r : order) {
    const std::optional<AxisLine> axis = AxisOf(regions[r].surface);
    if (!axis) continue;
    if (std::none_of(out.begin(), out.end(),
                     [&](const AxisLine& a) { return SameAxis(a, *axis, tol); })) {
      out.push_back(*axis);
    }
  }
  return out;
}

// True if every boundary curve of region r is a circle about `axis`.
bool BoundedByCoaxialCircles(const Topology& topology, int r, const AxisLine& axis,
                             const Tolerances& tol) {
  const std::vector<int>& loops = topology.regions[r].loops;
  if (loops.empty()) return false;
  for (const int l : loops) {
    for (const CurveUse& use : topology.loops[l].curves) {
      const CurveGeometry& g = topology.curves[use.curve].geometry;
      if (g.type != CurveGeometryType::kCircle || !Parallel(g.direction, axis.direction, tol) ||
          DistanceToLine(g.point, axis) > tol.distance) {
        return false;
      }
    }
  }
  return true;
}

bool OnAxis(const Topology& topology, std::span<const Region> regions, int r,
            const AxisLine& axis, const Tolerances& tol) {
  const Surface& s = regions[r].surface;
  if (const std::optional<AxisLine> own = AxisOf(s)) return SameAxis(*own, axis, tol);
  if (const auto* sphere = std::get_if<Sphere>(&s)) {
    return DistanceToLine(sphere->center, axis) <= tol.distance;
  }
  if (const auto* plane = std::get_if<Plane>(&s)) {
    return Parallel(plane->normal, axis.direction, tol) &&
           BoundedByCoaxialCircles(topology, r, axis, tol);
  }
  return false;
}

}  // namespace

std::vector<Feature> FindRevolutions(const Topology& topology, std::span<const Region> regions,
                                     const RegionGraph& graph, const Tolerances& tol) {
  std::vector<Feature> out;
  std::set<std::vector<int>> found;
  for (const AxisLine& axis : CandidateAxes(regions, tol)) {
    std::vector<char> member(regions.size(), 0);
    for (int r = 0; r < static_cast<int>(regions.size()); ++r) {
      member[r] = OnAxis(topology, regions, r, axis, tol);
    }
    for (std::vector<int>& group : graph.Components(member)) {
      const bool all_planes = std::all_of(group.begin(), group.end(), [&](int r) {
        return std::holds_alternative<Plane>(regions[r].surface);
      });
      if (group.size() < 2 || all_planes || !found.insert(group).second) continue;
      Feature f;
      f.type = FeatureType::kRevolution;
      f.direction = axis.direction;
      f.point = axis.point;
      f.regions = std::move(group);
      out.push_back(std::move(f));
    }
  }
  return out;
}

}  // namespace meshseg::features_internal
