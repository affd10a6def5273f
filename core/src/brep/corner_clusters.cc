#include "brep/corner_clusters.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

// Union-find root of corner k.
int Root(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

// True if every vertex of `c` lies within `on_surface` of both its regions'
// surfaces.
bool AlongIntersection(const TriMesh& mesh, const BoundaryCurve& c,
                       std::span<const Handle(Geom_Surface)> surfaces, double on_surface) {
  if (c.left_region < 0 || c.right_region < 0) return false;
  const Handle(Geom_Surface) pair[2] = {surfaces[c.left_region], surfaces[c.right_region]};
  if (pair[0].IsNull() || pair[1].IsNull()) return false;
  for (const int v : c.vertices) {
    const Eigen::Vector3d p = meshseg::ToEigen(mesh.point(OpenMesh::VertexHandle(v)));
    for (const Handle(Geom_Surface) & s : pair) {
      const std::optional<SurfacePoint> q = ClosestPoint(s, p);
      if (!q || std::abs(q->distance) > on_surface) return false;
    }
  }
  return true;
}

}  // namespace

CornerClusters ClusterCorners(const TriMesh& mesh, const Topology& topology,
                              std::span<const Handle(Geom_Surface)> surfaces, double on_surface) {
  const int n = static_cast<int>(topology.corners.size());
  CornerClusters out;
  out.artifact.assign(topology.curves.size(), 0);
  std::vector<int> parent(n);
  for (int k = 0; k < n; ++k) parent[k] = k;
  for (const BoundaryCurve& c : topology.curves) {
    if (!c.junction_artifact || AlongIntersection(mesh, c, surfaces, on_surface)) continue;
    out.artifact[c.id] = 1;
    const int a = Root(parent, c.start_corner);
    const int b = Root(parent, c.end_corner);
    parent[std::max(a, b)] = std::min(a, b);
  }
  out.cluster.resize(n);
  std::map<int, std::vector<int>> members;
  for (int k = 0; k < n; ++k) {
    out.cluster[k] = Root(parent, k);
    members[out.cluster[k]].push_back(k);
  }
  std::map<int, size_t> old_size;
  for (const Corner& c : topology.corners) ++old_size[c.cluster];
  for (const auto& [cluster, ids] : members) {
    // The topology's cluster of these corners, if it is the same set.
    const int old = topology.corners[cluster].cluster;
    const bool same = old_size[old] == ids.size() &&
                      std::all_of(ids.begin(), ids.end(),
                                  [&](int k) { return topology.corners[k].cluster == old; });
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::vector<int>& regions = out.regions[cluster];
    for (const int k : ids) {
      mean += meshseg::ToEigen(mesh.point(OpenMesh::VertexHandle(topology.corners[k].vertex)));
      for (const int r : topology.corners[k].regions) {
        if (r >= 0 && std::find(regions.begin(), regions.end(), r) == regions.end()) {
          regions.push_back(r);
        }
      }
    }
    out.start[cluster] =
        same ? topology.corners[cluster].position : mean / static_cast<double>(ids.size());
  }
  return out;
}

}  // namespace meshseg::brep_internal
