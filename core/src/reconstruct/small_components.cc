#include "reconstruct/small_components.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "mesh/union_find.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

int64_t DropSmallComponents(double min_fraction, IsoSurface* surface) {
  const size_t n = surface->vertices.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : surface->triangles) {
    for (int i = 1; i < 3; ++i) {
      const int a = FindRoot(parent, t[0]), b = FindRoot(parent, t[i]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<int64_t> faces(n, 0);
  for (const auto& t : surface->triangles) ++faces[FindRoot(parent, t[0])];
  const int64_t largest = *std::max_element(faces.begin(), faces.end());
  int64_t dropped = 0;
  for (size_t v = 0; v < n; ++v) {
    dropped += faces[v] > 0 && faces[v] < min_fraction * static_cast<double>(largest);
  }
  if (dropped == 0) return 0;
  const auto keep = [&](int v) { return faces[FindRoot(parent, v)] >= min_fraction * largest; };
  std::vector<int> renumber(n, -1);
  IsoSurface kept;
  for (size_t v = 0; v < n; ++v) {
    if (!keep(static_cast<int>(v))) continue;
    renumber[v] = static_cast<int>(kept.vertices.size());
    kept.vertices.push_back(surface->vertices[v]);
    kept.to_smooth.push_back(surface->to_smooth[v]);
  }
  for (const auto& t : surface->triangles) {
    if (renumber[t[0]] < 0) continue;
    kept.triangles.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
  }
  *surface = std::move(kept);
  return dropped;
}

}  // namespace meshseg::reconstruct_internal
