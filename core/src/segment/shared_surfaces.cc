#include "segment/shared_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>
#include <variant>

#include "meshseg/fit.h"
#include "segment/exact_hypotheses.h"

namespace meshseg::segment_internal {
namespace {

// Corners checked per region: every k-th of a larger set (a first pass on
// kQuickCorners of them rejects most pairs at once).
constexpr std::size_t kMaxCheckedCorners = 400;
constexpr std::size_t kQuickCorners = 8;

bool AllOn(const FacetMesh& fm, const std::vector<int>& corners, const Surface& s, double tau,
           std::size_t max_count) {
  const std::size_t stride = std::max<std::size_t>(1, corners.size() / max_count);
  for (std::size_t i = 0; i < corners.size(); i += stride) {
    if (!(std::abs(SignedDistance(s, fm.points[corners[i]])) <= tau)) return false;
  }
  return true;
}

// A coarse key of a surface's parameters (direction with its sign made
// canonical, offset or radius, at kKeyStep of the diagonal or radians):
// surfaces that can coincide share it, or lie one step apart, so pairs are
// only tried within a key and its neighbours.
constexpr double kKeyStep = 1e-3;

std::array<long long, 3> KeyOf(const Surface& s, double diagonal) {
  auto q = [&](double x, double unit) { return std::llround(x / (kKeyStep * unit)); };
  auto canonical = [](Eigen::Vector3d d) {
    const int k = d.cwiseAbs().maxCoeff() == std::abs(d.x())
                      ? 0
                      : (d.cwiseAbs().maxCoeff() == std::abs(d.y()) ? 1 : 2);
    return d[k] < 0.0 ? Eigen::Vector3d(-d) : d;
  };
  if (const auto* p = std::get_if<Plane>(&s)) {
    const Eigen::Vector3d n = canonical(p->normal);
    return {q(n.x(), 1.0), q(n.y(), 1.0), q(n.dot(p->point), diagonal)};
  }
  if (const auto* c = std::get_if<Cylinder>(&s)) {
    const Eigen::Vector3d a = canonical(c->axis_direction);
    return {q(a.x(), 1.0), q(a.y(), 1.0), q(c->radius, diagonal)};
  }
  if (const auto* c = std::get_if<Cone>(&s)) {
    return {q(c->apex.x(), diagonal), q(c->apex.y(), diagonal), q(c->half_angle, 1.0)};
  }
  if (const auto* c = std::get_if<Sphere>(&s)) {
    return {q(c->center.x(), diagonal), q(c->center.y(), diagonal), q(c->radius, diagonal)};
  }
  if (const auto* c = std::get_if<Torus>(&s)) {
    return {q(c->center.x(), diagonal), q(c->major_radius, diagonal), q(c->minor_radius, diagonal)};
  }
  return {0, 0, 0};
}

int Find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

std::vector<SharedSurface> GroupSharedSurfaces(const FacetMesh& fm,
                                               const std::vector<ExactRegion>& regions, double tau,
                                               std::vector<int>* surface_of_region) {
  const int n = static_cast<int>(regions.size());
  std::vector<std::vector<int>> corners(n);
  for (int r = 0; r < n; ++r) corners[r] = CornersOf(fm, regions[r].facets);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, std::array<long long, 3>>, std::vector<int>> by_key;
  for (int r = 0; r < n; ++r) {
    if (regions[r].type == SurfaceType::kFreeform) continue;
    by_key[{static_cast<int>(regions[r].type), KeyOf(regions[r].surface, fm.diagonal)}].push_back(
        r);
  }
  auto try_join = [&](int a, int b) {
    if (regions[b].type != regions[a].type || Find(parent, a) == Find(parent, b)) return;
    const Surface& sa = regions[a].surface;
    const Surface& sb = regions[b].surface;
    if (!AllOn(fm, corners[b], sa, tau, kQuickCorners) ||
        !AllOn(fm, corners[a], sb, tau, kQuickCorners) ||
        !AllOn(fm, corners[b], sa, tau, kMaxCheckedCorners) ||
        !AllOn(fm, corners[a], sb, tau, kMaxCheckedCorners)) {
      return;
    }
    parent[Find(parent, a)] = Find(parent, b);
  };
  for (const auto& [key, members] : by_key) {
    for (int d0 = -1; d0 <= 1; ++d0) {
      for (int d1 = -1; d1 <= 1; ++d1) {
        for (int d2 = -1; d2 <= 1; ++d2) {
          const auto near = by_key.find(
              {key.first, {key.second[0] + d0, key.second[1] + d1, key.second[2] + d2}});
          if (near == by_key.end() || near->first < key) continue;
          for (const int a : members) {
            for (const int b : near->second) {
              if (near->first == key && b <= a) continue;
              try_join(a, b);
            }
          }
        }
      }
    }
  }
  std::vector<std::vector<int>> groups(n);
  for (int r = 0; r < n; ++r) groups[Find(parent, r)].push_back(r);
  std::vector<SharedSurface> out;
  surface_of_region->assign(n, -1);
  auto add = [&](const std::vector<int>& members, const Surface& surface) {
    const int id = static_cast<int>(out.size());
    SharedSurface s;
    s.id = id;
    s.type = regions[members.front()].type;
    s.surface = surface;
    s.regions = members;
    for (const int r : members) (*surface_of_region)[r] = id;
    out.push_back(std::move(s));
  };
  for (int r = 0; r < n; ++r) {
    if ((*surface_of_region)[r] >= 0 || groups[Find(parent, r)].empty()) continue;
    const std::vector<int>& members = groups[Find(parent, r)];
    if (members.size() == 1) {
      add(members, regions[r].surface);
      continue;
    }
    std::vector<int> facets;
    for (const int m : members) {
      facets.insert(facets.end(), regions[m].facets.begin(), regions[m].facets.end());
    }
    if (const std::optional<Surface> joint = FitExactly(fm, regions[r].type, facets, tau)) {
      add(members, *joint);
    } else {
      for (const int m : members) add({m}, regions[m].surface);
    }
  }
  return out;
}

}  // namespace meshseg::segment_internal
