#include "topology/place_corners.h"

#include <algorithm>
#include <map>
#include <optional>

#include "topology/chain_curves.h"
#include "topology/snap_corner.h"

namespace meshseg::topology_internal {
namespace {

// Sorted labels around v, -1 for the mesh border and unlabelled faces.
std::vector<int> LabelsAround(const TriMesh& mesh, std::span<const int> labels, int v) {
  std::vector<int> out;
  for (OpenMesh::HalfedgeHandle h : mesh.voh_range(OpenMesh::VertexHandle(v))) {
    out.push_back(LeftLabel(mesh, labels, h));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Union-find root of corner k.
int ClusterRoot(std::vector<int>& parent, int k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

}  // namespace

void PlaceCorners(const TriMesh& mesh, std::span<const int> labels,
                  std::span<const Region> regions, const std::vector<int>& corner_vertices,
                  double snap_distance, Topology* topo) {
  const int n = static_cast<int>(corner_vertices.size());
  std::vector<int> parent(n);
  for (int k = 0; k < n; ++k) parent[k] = k;
  for (const BoundaryCurve& c : topo->curves) {
    if (!c.junction_artifact) continue;
    const int a = ClusterRoot(parent, c.start_corner);
    const int b = ClusterRoot(parent, c.end_corner);
    parent[std::max(a, b)] = std::min(a, b);
  }
  for (int k = 0; k < n; ++k) {
    Corner c;
    c.id = k;
    c.vertex = corner_vertices[k];
    c.cluster = ClusterRoot(parent, k);
    c.regions = LabelsAround(mesh, labels, c.vertex);
    topo->corners.push_back(std::move(c));
  }
  // One position per cluster: its mean vertex, snapped with all its regions.
  std::map<int, std::vector<int>> members;
  for (const Corner& c : topo->corners) members[c.cluster].push_back(c.id);
  for (const auto& [cluster, ids] : members) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::vector<int> cluster_regions;
    for (const int id : ids) {
      mean += ToEigen(mesh.point(OpenMesh::VertexHandle(topo->corners[id].vertex)));
      for (const int r : topo->corners[id].regions) cluster_regions.push_back(r);
    }
    mean /= static_cast<double>(ids.size());
    std::sort(cluster_regions.begin(), cluster_regions.end());
    cluster_regions.erase(std::unique(cluster_regions.begin(), cluster_regions.end()),
                          cluster_regions.end());
    std::vector<const Surface*> surfaces;
    for (const int r : cluster_regions) {
      if (r >= 0) surfaces.push_back(&regions[r].surface);
    }
    const std::optional<Eigen::Vector3d> snapped =
        SnapCorner(mean, surfaces, snap_distance);
    for (const int id : ids) {
      topo->corners[id].position = snapped ? *snapped : mean;
      topo->corners[id].snapped = snapped.has_value();
    }
  }
  for (const BoundaryCurve& curve : topo->curves) {
    if (curve.start_corner >= 0) topo->corners[curve.start_corner].curves.push_back(curve.id);
    if (curve.end_corner >= 0) topo->corners[curve.end_corner].curves.push_back(curve.id);
  }
}

}  // namespace meshseg::topology_internal
