// Outlier flags for the input points: isolated points and points lying off
// the surface their neighbours describe. Our addition to seed 001: its linear
// local fits (eq. 3) tilt towards such points, most when their normals are
// random; the graph cut then only has to repair what remains.
#ifndef MESHSEG_RECONSTRUCT_OUTLIERS_H_
#define MESHSEG_RECONSTRUCT_OUTLIERS_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"

namespace meshseg::reconstruct_internal {

// Returns, per point, the mean distance to its 6 nearest other points
// (≈ sqrt(area / count) on a uniformly sampled surface, large for isolated
// outliers).
std::vector<double> MeanNeighborDistances(const std::vector<Eigen::Vector3d>& points,
                                          const mesh_internal::PointIndex& index);

// Returns 1 per point whose mean distance to its 6 nearest neighbours
// (`spread`) exceeds `isolated_distance`, or whose distance to the
// least-squares plane of its `k` nearest other points exceeds
// `off_surface_distance`, or (with `normals` given) whose normal is more than
// 60° from the mean normal of those neighbours; else 0. Distances in model
// units.
std::vector<uint8_t> OutlierFlags(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& normals,
                                  const mesh_internal::PointIndex& index,
                                  const std::vector<double>& spread, int k,
                                  double isolated_distance, double off_surface_distance);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_OUTLIERS_H_
