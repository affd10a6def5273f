#include "segment/shared_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>
#include <variant>

#include <tbb/parallel_for.h>

#include "meshseg/fit.h"
#include "segment/energy.h"
#include "segment/exact_fit.h"

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
// canonical, offset or radius, position, at kKeyStep of the diagonal or
// radians): surfaces that can coincide share it, or lie one step apart in
// each, so pairs are only tried within a key and its neighbours. An axis's
// position is its point nearest the frame's origin (the box centre), taken
// along a fixed oblique direction: parallel cylinders of one radius (a pin
// array, the holes of a grid) differ there, and two fits of one cylinder
// agree there to their axes' angle times the box's size, the same
// resolution as the direction's own step.
constexpr double kKeyStep = 1e-3;
using Key = std::array<long long, 4>;

Key KeyOf(const Surface& s, double diagonal) {
  auto q = [&](double x, double unit) { return std::llround(x / (kKeyStep * unit)); };
  auto canonical = [](Eigen::Vector3d d) {
    const int k = d.cwiseAbs().maxCoeff() == std::abs(d.x())
                      ? 0
                      : (d.cwiseAbs().maxCoeff() == std::abs(d.y()) ? 1 : 2);
    return d[k] < 0.0 ? Eigen::Vector3d(-d) : d;
  };
  const Eigen::Vector3d oblique = Eigen::Vector3d(0.36, 0.48, 0.8);  // unit, on no plane of axes
  if (const auto* p = std::get_if<Plane>(&s)) {
    const Eigen::Vector3d n = canonical(p->normal);
    return {q(n.x(), 1.0), q(n.y(), 1.0), q(n.dot(p->point), diagonal), 0};
  }
  if (const auto* c = std::get_if<Cylinder>(&s)) {
    const Eigen::Vector3d a = canonical(c->axis_direction);
    const Eigen::Vector3d foot = c->axis_origin - c->axis_origin.dot(a) * a;
    return {q(a.x(), 1.0), q(a.y(), 1.0), q(c->radius, diagonal), q(foot.dot(oblique), diagonal)};
  }
  if (const auto* c = std::get_if<Cone>(&s)) {
    return {q(c->apex.x(), diagonal), q(c->apex.y(), diagonal), q(c->half_angle, 1.0),
            q(c->apex.z(), diagonal)};
  }
  if (const auto* c = std::get_if<Sphere>(&s)) {
    return {q(c->center.x(), diagonal), q(c->center.y(), diagonal), q(c->radius, diagonal),
            q(c->center.z(), diagonal)};
  }
  if (const auto* c = std::get_if<Torus>(&s)) {
    return {q(c->center.x(), diagonal), q(c->major_radius, diagonal), q(c->minor_radius, diagonal),
            q(c->center.y(), diagonal)};
  }
  return {0, 0, 0, 0};
}

// Union by size keeps every tree shallow, so the root is found by reading
// alone: the pairs of a large group of one surface (every cap of a pin
// array in one plane) are mostly found joined already, at two reads each.
using TypedKey = std::pair<int, Key>;  // (type, key)
struct TypedKeyHash {
  std::size_t operator()(const TypedKey& k) const {
    std::size_t h = std::hash<int>()(k.first);
    for (const long long x : k.second) h = h * 1000003u ^ std::hash<long long>()(x);
    return h;
  }
};

int Find(const std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x];
  return x;
}

}  // namespace

std::vector<SharedSurface> GroupSharedSurfaces(const FacetMesh& fm,
                                               const std::vector<ExactRegion>& regions, double tau,
                                               std::vector<int>* surface_of_region) {
  const int n = static_cast<int>(regions.size());
  std::vector<std::vector<int>> corners(n);
  tbb::parallel_for(0, n, [&](int r) { corners[r] = CornersOf(fm, regions[r].facets); });
  std::vector<int> parent(n), size(n, 1);
  std::iota(parent.begin(), parent.end(), 0);
  std::unordered_map<TypedKey, std::vector<int>, TypedKeyHash> by_key;
  for (int r = 0; r < n; ++r) {
    if (regions[r].type == SurfaceType::kFreeform) continue;
    by_key[{static_cast<int>(regions[r].type), KeyOf(regions[r].surface, fm.diagonal)}].push_back(
        r);
  }
  // a and b: of one key, so of one type.
  auto try_join = [&](int a, int b) {
    int root_a = Find(parent, a), root_b = Find(parent, b);
    if (root_a == root_b) return;
    const Surface& sa = regions[a].surface;
    const Surface& sb = regions[b].surface;
    if (!AllOn(fm, corners[b], sa, tau, kQuickCorners) ||
        !AllOn(fm, corners[a], sb, tau, kQuickCorners) ||
        !AllOn(fm, corners[b], sa, tau, kMaxCheckedCorners) ||
        !AllOn(fm, corners[a], sb, tau, kMaxCheckedCorners)) {
      return;
    }
    if (size[root_a] < size[root_b]) std::swap(root_a, root_b);
    parent[root_b] = root_a;
    size[root_a] += size[root_b];
  };
  // The key and its neighbours one step in each place, each pair of keys
  // once: the offsets whose first step that is not 0 is +1, and 0.
  std::vector<Key> forward;
  for (int d = 0; d < 81; ++d) {
    Key step;
    for (int k = 0, m = d; k < 4; ++k, m /= 3) step[k] = m % 3 - 1;
    const auto first = std::find_if(step.begin(), step.end(), [](long long x) { return x != 0; });
    if (first == step.end() || *first > 0) forward.push_back(step);
  }
  for (const auto& [key, members] : by_key) {
    for (const Key& step : forward) {
      Key next = key.second;
      for (int k = 0; k < 4; ++k) next[k] += step[k];
      const auto near = by_key.find({key.first, next});
      if (near == by_key.end()) continue;
      // Members ascend: within one key, each pair once (b after a).
      const std::vector<int>& others = near->second;
      const bool same_key = &others == &members;
      for (std::size_t i = 0; i < members.size(); ++i) {
        for (std::size_t j = same_key ? i + 1 : 0; j < others.size(); ++j) {
          try_join(members[i], others[j]);
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
  // The joint fit of each group of several regions (independent fits).
  std::vector<int> joined;  // roots of such groups
  for (int r = 0; r < n; ++r) {
    if (parent[r] == r && groups[r].size() > 1) joined.push_back(r);
  }
  std::vector<std::optional<Surface>> joint(n);
  tbb::parallel_for(std::size_t{0}, joined.size(), [&](std::size_t i) {
    const std::vector<int>& members = groups[joined[i]];
    std::vector<int> facets;
    for (const int m : members) {
      facets.insert(facets.end(), regions[m].facets.begin(), regions[m].facets.end());
    }
    joint[joined[i]] = FitExactly(fm, regions[members.front()].type, facets, tau);
  });
  // A group is one label of E iff that lowers E (energy.h: ExactJoinDelta):
  // its joint fit holding every corner within tau (each facet lay on its own
  // region's surface through the same corners: data cost 0), one label cost
  // instead of one per region; else the data cost is infinite.
  auto joins = [&](const std::vector<int>& members, bool fits) {
    std::vector<std::size_t> counts;
    for (const int m : members) counts.push_back(corners[m].size());
    return ExactJoinDelta(regions[members.front()].type, counts,
                          fits ? 0.0 : std::numeric_limits<double>::infinity()) < 0.0;
  };
  for (int r = 0; r < n; ++r) {
    const int root = Find(parent, r);
    if ((*surface_of_region)[r] >= 0 || groups[root].empty()) continue;
    const std::vector<int>& members = groups[root];
    if (members.size() == 1) {
      add(members, regions[r].surface);
    } else if (joins(members, joint[root].has_value())) {
      add(members, *joint[root]);
    } else {
      for (const int m : members) add({m}, regions[m].surface);
    }
  }
  return out;
}

}  // namespace meshseg::segment_internal
