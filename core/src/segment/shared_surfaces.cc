#include "segment/shared_surfaces.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "meshseg/fit.h"
#include "segment/exact_hypotheses.h"

namespace meshseg::segment_internal {
namespace {

// Corners checked per region: every k-th of a larger set (a first pass on
// kQuickCorners of them rejects most pairs at once).
constexpr std::size_t kMaxCheckedCorners = 400;
constexpr std::size_t kQuickCorners = 8;

std::vector<int> CornersOf(const FacetMesh& fm, const std::vector<int>& facets) {
  std::vector<int> v;
  for (const int f : facets) v.insert(v.end(), fm.corners[f].begin(), fm.corners[f].end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

bool AllOn(const FacetMesh& fm, const std::vector<int>& corners, const Surface& s, double tau,
           std::size_t max_count) {
  const std::size_t stride = std::max<std::size_t>(1, corners.size() / max_count);
  for (std::size_t i = 0; i < corners.size(); i += stride) {
    if (!(std::abs(SignedDistance(s, fm.points[corners[i]])) <= tau)) return false;
  }
  return true;
}

int Find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

std::vector<SharedSurface> GroupSharedSurfaces(const FacetMesh& fm,
                                               const std::vector<ExactRegion>& regions,
                                               double tau, std::vector<int>* surface_of_region) {
  const int n = static_cast<int>(regions.size());
  std::vector<std::vector<int>> corners(n);
  for (int r = 0; r < n; ++r) corners[r] = CornersOf(fm, regions[r].facets);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int a = 0; a < n; ++a) {
    if (regions[a].type == SurfaceType::kFreeform) continue;
    for (int b = 0; b < a; ++b) {
      if (regions[b].type != regions[a].type || Find(parent, a) == Find(parent, b)) continue;
      const Surface& sa = regions[a].surface;
      const Surface& sb = regions[b].surface;
      if (!AllOn(fm, corners[b], sa, tau, kQuickCorners) ||
          !AllOn(fm, corners[a], sb, tau, kQuickCorners) ||
          !AllOn(fm, corners[b], sa, tau, kMaxCheckedCorners) ||
          !AllOn(fm, corners[a], sb, tau, kMaxCheckedCorners)) {
        continue;
      }
      parent[Find(parent, a)] = Find(parent, b);
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
