#include "reconstruct/small_components.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mesh/union_find.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

int64_t DropSmallComponents(double min_fraction, double min_thickness, IsoSurface* surface) {
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
  std::vector<double> area(n, 0.0), volume(n, 0.0);
  for (const auto& t : surface->triangles) {
    const int root = FindRoot(parent, t[0]);
    const Eigen::Vector3d& a = surface->vertices[t[0]];
    const Eigen::Vector3d& b = surface->vertices[t[1]];
    const Eigen::Vector3d& c = surface->vertices[t[2]];
    ++faces[root];
    area[root] += 0.5 * (b - a).cross(c - a).norm();
    volume[root] += a.dot(b.cross(c)) / 6.0;  // divergence theorem
  }
  const size_t largest =
      static_cast<size_t>(std::max_element(faces.begin(), faces.end()) - faces.begin());
  std::vector<uint8_t> kept_root(n, 0);
  int64_t dropped = 0;
  for (size_t v = 0; v < n; ++v) {
    if (faces[v] == 0) continue;
    kept_root[v] = v == largest || (faces[v] >= min_fraction * static_cast<double>(faces[largest]) &&
                                    2.0 * std::abs(volume[v]) >= min_thickness * area[v]);
    dropped += !kept_root[v];
  }
  if (dropped == 0) return 0;
  const auto keep = [&](int v) { return kept_root[FindRoot(parent, v)] != 0; };
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
