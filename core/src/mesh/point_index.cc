#include "mesh/point_index.h"

#include <nanoflann.hpp>

namespace meshseg::mesh_internal {
namespace {

// nanoflann's dataset interface over a vector of Eigen points.
struct Cloud {
  const std::vector<Eigen::Vector3d>& points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                   Cloud, 3, uint32_t>;

}  // namespace

struct PointIndex::Tree {
  explicit Tree(const std::vector<Eigen::Vector3d>& points)
      : cloud{points}, kd(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
  Cloud cloud;
  KdTree kd;
};

PointIndex::PointIndex(const std::vector<Eigen::Vector3d>& points)
    : points_(points), tree_(std::make_unique<Tree>(points)) {}

PointIndex::~PointIndex() = default;

void PointIndex::Nearest(const Eigen::Vector3d& q, int k, std::vector<uint32_t>* indices,
                         std::vector<double>* dist2) const {
  indices->resize(k);
  dist2->resize(k);
  const size_t n = tree_->kd.knnSearch(q.data(), k, indices->data(), dist2->data());
  indices->resize(n);
  dist2->resize(n);
}

uint32_t PointIndex::Closest(const Eigen::Vector3d& q) const {
  uint32_t index = 0;
  double dist2 = 0.0;
  tree_->kd.knnSearch(q.data(), 1, &index, &dist2);
  return index;
}

void PointIndex::WithinRadius(const Eigen::Vector3d& q, double radius,
                              std::vector<std::pair<uint32_t, double>>* found) const {
  found->clear();
  tree_->kd.radiusSearch(q.data(), radius * radius, *found, nanoflann::SearchParams(32, 0, true));
}

void PointIndex::WithinRadiusUnordered(const Eigen::Vector3d& q, double radius,
                                       std::vector<std::pair<uint32_t, double>>* found) const {
  found->clear();
  tree_->kd.radiusSearch(q.data(), radius * radius, *found, nanoflann::SearchParams(32, 0, false));
}

std::vector<uint32_t> PointIndex::SpatialOrder() const {
  return std::vector<uint32_t>(tree_->kd.vAcc.begin(), tree_->kd.vAcc.end());
}

}  // namespace meshseg::mesh_internal
