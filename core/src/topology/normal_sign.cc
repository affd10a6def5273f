#include "topology/normal_sign.h"

#include "meshseg/fit.h"

namespace meshseg::topology_internal {

std::vector<int> RegionNormalSigns(const TriMesh& mesh, std::span<const int> face_labels,
                                   std::span<const Region> regions) {
  std::vector<double> agreement(regions.size(), 0.0);
  for (OpenMesh::FaceHandle f : mesh.faces()) {
    const int label = face_labels[f.idx()];
    if (label < 0) continue;
    const Eigen::Vector3d c = ToEigen(mesh.calc_face_centroid(f));
    const Eigen::Vector3d n = ToEigen(mesh.normal(f));
    const double area = mesh.calc_face_area(f);
    agreement[label] += area * Project(regions[label].surface, c, n).normal.dot(n);
  }
  std::vector<int> signs(regions.size(), 0);
  for (size_t k = 0; k < regions.size(); ++k) {
    if (agreement[k] > 0.0) signs[k] = 1;
    if (agreement[k] < 0.0) signs[k] = -1;
  }
  return signs;
}

}  // namespace meshseg::topology_internal
