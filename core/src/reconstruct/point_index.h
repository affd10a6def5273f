// k-nearest-neighbour and radius queries over a fixed set of 3D points
// (nanoflann k-d tree). Shared by the normal estimation, the covering and the
// evaluation of f.
#ifndef MESHSEG_RECONSTRUCT_POINT_INDEX_H_
#define MESHSEG_RECONSTRUCT_POINT_INDEX_H_

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// An index over `points`, which must outlive it and stay unchanged.
class PointIndex {
 public:
  explicit PointIndex(const std::vector<Eigen::Vector3d>& points);
  ~PointIndex();
  PointIndex(const PointIndex&) = delete;
  PointIndex& operator=(const PointIndex&) = delete;

  // Fills `indices` and `dist2` (squared distances) with the min(k, size)
  // points nearest to `q`, nearest first. A member point finds itself.
  void Nearest(const Eigen::Vector3d& q, int k, std::vector<uint32_t>* indices,
               std::vector<double>* dist2) const;

  // Fills `found` with (index, squared distance) of the points with
  // |p − q| < radius, nearest first.
  void WithinRadius(const Eigen::Vector3d& q, double radius,
                    std::vector<std::pair<uint32_t, double>>* found) const;

  size_t size() const { return points_.size(); }

 private:
  struct Tree;
  const std::vector<Eigen::Vector3d>& points_;
  std::unique_ptr<Tree> tree_;
};

// Returns, per point, the mean distance to its 6 nearest other points
// (≈ sqrt(area / count) on a uniformly sampled surface, large for isolated
// outliers).
std::vector<double> MeanNeighborDistances(const std::vector<Eigen::Vector3d>& points,
                                          const PointIndex& index);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_POINT_INDEX_H_
