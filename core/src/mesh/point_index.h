// k-nearest-neighbour and radius queries over a fixed set of 3D points
// (nanoflann k-d tree). One index for every stage that searches points:
// reconstruction (normals, covering, f), subdivision footpoints, Hausdorff
// distances, and labels carried from a mesh to the cloud it was built from.
#ifndef MESHSEG_MESH_POINT_INDEX_H_
#define MESHSEG_MESH_POINT_INDEX_H_

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace meshseg::mesh_internal {

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

  // The index of the point nearest to `q` (ties: any of them). The index
  // must not be empty.
  uint32_t Closest(const Eigen::Vector3d& q) const;

  // Fills `found` with (index, squared distance) of the points with
  // |p − q| < radius, nearest first.
  void WithinRadius(const Eigen::Vector3d& q, double radius,
                    std::vector<std::pair<uint32_t, double>>* found) const;

  // As WithinRadius, in no particular order (saves the sort; for callers
  // that visit every point found).
  void WithinRadiusUnordered(const Eigen::Vector3d& q, double radius,
                             std::vector<std::pair<uint32_t, double>>* found) const;

  // Every point's index once, in the tree's order: points of one leaf
  // bucket, then of the next, depth first. Queries issued in this order touch
  // the tree and the points in a cache-friendly sequence.
  std::vector<uint32_t> SpatialOrder() const;

  size_t size() const { return points_.size(); }

 private:
  struct Tree;
  const std::vector<Eigen::Vector3d>& points_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_POINT_INDEX_H_
