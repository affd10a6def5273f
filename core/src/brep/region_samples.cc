#include "brep/region_samples.h"

#include <algorithm>

namespace meshseg::brep_internal {

std::vector<RegionSamples> SampleRegions(const TriMesh& mesh, std::span<const int> face_labels,
                                         int region_count) {
  std::vector<RegionSamples> out(region_count);
  std::vector<int> face_count(region_count, 0);
  for (const int label : face_labels) {
    if (label >= 0) ++face_count[label];
  }
  // Every stride-th face of a region, so the samples spread over all of it.
  std::vector<int> stride(region_count), seen(region_count, 0);
  for (int r = 0; r < region_count; ++r) {
    stride[r] = std::max(1, face_count[r] / kMaxFaceSamples);
  }
  // A vertex on a boundary belongs to every region around it: ids are
  // gathered per region and made unique after the pass.
  std::vector<std::vector<int>> vertex_ids(region_count);
  for (OpenMesh::FaceHandle f : mesh.faces()) {
    const int label = face_labels[f.idx()];
    if (label < 0) continue;
    for (OpenMesh::VertexHandle v : mesh.fv_range(f)) vertex_ids[label].push_back(v.idx());
    if (seen[label]++ % stride[label] != 0) continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (OpenMesh::VertexHandle v : mesh.fv_range(f)) centroid += ToEigen(mesh.point(v));
    out[label].face_centroids.push_back(centroid / 3.0);
    out[label].face_normals.push_back(ToEigen(mesh.normal(f)).normalized());
  }
  for (int r = 0; r < region_count; ++r) {
    std::vector<int>& ids = vertex_ids[r];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    out[r].points.reserve(ids.size());
    for (const int v : ids) out[r].points.push_back(ToEigen(mesh.point(OpenMesh::VertexHandle(v))));
  }
  return out;
}

}  // namespace meshseg::brep_internal
