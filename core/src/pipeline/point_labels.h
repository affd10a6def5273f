// Labels the points of a cloud by the nearest face of the mesh made from it.
#ifndef MESHSEG_PIPELINE_POINT_LABELS_H_
#define MESHSEG_PIPELINE_POINT_LABELS_H_

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"

namespace meshseg::pipeline_internal {

// Returns one label per point: the label of the face of `mesh` closest to
// it (point-to-triangle distance over the faces around the nearest vertex),
// or -1 where is_outlier[k] is set. `face_labels` has one entry per face;
// `is_outlier` is empty or one flag per point.
std::vector<int> PointLabels(const TriMesh& mesh, std::span<const int> face_labels,
                             std::span<const Eigen::Vector3d> points,
                             std::span<const uint8_t> is_outlier);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_POINT_LABELS_H_
