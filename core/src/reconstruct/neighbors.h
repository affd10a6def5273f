// The k nearest neighbours of every point, found once and shared by the
// stages that need them (outlier test, point spacing, normals): at a million
// points each k-NN pass costs seconds.
#ifndef MESHSEG_RECONSTRUCT_NEIGHBORS_H_
#define MESHSEG_RECONSTRUCT_NEIGHBORS_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"

namespace meshseg::reconstruct_internal {

// Row i holds the k points nearest to point i other than itself, nearest
// first; when there are fewer than k others, the row is padded with i.
struct NeighborTable {
  int k = 0;
  std::vector<uint32_t> index;  // n × k, row-major

  size_t size() const { return k == 0 ? 0 : index.size() / k; }
  const uint32_t* Row(size_t i) const { return index.data() + i * k; }
};

// The table of `points` (indexed by `index`), found in parallel in the
// index's spatial order (the result does not depend on it).
NeighborTable NearestOthers(const std::vector<Eigen::Vector3d>& points,
                            const mesh_internal::PointIndex& index, int k);

// The first `k` columns of `table` (k ≤ table.k).
NeighborTable FirstColumns(const NeighborTable& table, int k);

// The table of the points not `removed`, numbered in their order, from the
// table of all points: exact, because removing points brings no other point
// nearer. A row that names a removed point is found again on `kept_index`
// (over `kept`, the points not removed, in order).
NeighborTable KeptNeighbors(const NeighborTable& all, const std::vector<uint8_t>& removed,
                            const std::vector<Eigen::Vector3d>& kept,
                            const mesh_internal::PointIndex& kept_index);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_NEIGHBORS_H_
