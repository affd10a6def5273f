#include "reconstruct/winding_number.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kFourPi = 4.0 * std::numbers::pi;
// (1/6) Σ_{k=1..6} sqrt(k): see PointAreas.
constexpr double kMeanOfSixRoots = 1.805;

}  // namespace

WindingNumber::WindingNumber(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Eigen::Vector3d>& outward,
                             const std::vector<double>& areas) {
  const int n = static_cast<int>(points.size());
  points_ = points;
  weighted_normals_.resize(n);
  smoothing_.resize(n);
  for (int i = 0; i < n; ++i) {
    weighted_normals_[i] = areas[i] * outward[i];
    smoothing_[i] = areas[i] / std::numbers::pi;
  }
  if (n > 0) Build(0, n);
}

// Builds the node over [first, first + count) of the arrays, which it
// reorders so that each node's points are contiguous; returns its index.
int WindingNumber::Build(int first, int count) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  double area = 0.0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = points_[first], hi = points_[first];
  Eigen::Vector3d dipole = Eigen::Vector3d::Zero();
  for (int i = first; i < first + count; ++i) {
    const double a = smoothing_[i] * std::numbers::pi;
    area += a;
    weighted += a * points_[i];
    dipole += weighted_normals_[i];
    lo = lo.cwiseMin(points_[i]);
    hi = hi.cwiseMax(points_[i]);
  }
  const Eigen::Vector3d center = area > 0.0 ? Eigen::Vector3d(weighted / area) : 0.5 * (lo + hi);
  double radius = 0.0;
  for (int i = first; i < first + count; ++i) {
    radius = std::max(radius, (points_[i] - center).norm());
  }
  nodes_[id].center = center;
  nodes_[id].dipole = dipole;
  nodes_[id].radius = radius;
  nodes_[id].first = first;
  nodes_[id].count = count;
  if (count <= kLeafPoints) return id;
  // Split at the median along the longest side of the box.
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), first);
  const int half = count / 2;
  std::nth_element(order.begin(), order.begin() + half, order.end(),
                   [&](int a, int b) { return points_[a][axis] < points_[b][axis]; });
  std::vector<Eigen::Vector3d> p(count), wn(count);
  std::vector<double> s(count);
  for (int k = 0; k < count; ++k) {
    p[k] = points_[order[k]];
    wn[k] = weighted_normals_[order[k]];
    s[k] = smoothing_[order[k]];
  }
  std::copy(p.begin(), p.end(), points_.begin() + first);
  std::copy(wn.begin(), wn.end(), weighted_normals_.begin() + first);
  std::copy(s.begin(), s.end(), smoothing_.begin() + first);
  const int left = Build(first, half);
  const int right = Build(first + half, count - half);
  nodes_[id].child[0] = left;
  nodes_[id].child[1] = right;
  return id;
}

double WindingNumber::Direct(int first, int count, const Eigen::Vector3d& q) const {
  double sum = 0.0;
  for (int i = first; i < first + count; ++i) {
    const Eigen::Vector3d d = points_[i] - q;
    const double r2 = d.squaredNorm() + smoothing_[i];
    sum += weighted_normals_[i].dot(d) / (r2 * std::sqrt(r2));
  }
  return sum;
}

double WindingNumber::operator()(const Eigen::Vector3d& q) const {
  if (nodes_.empty()) return 0.0;
  double sum = 0.0;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const Eigen::Vector3d d = node.center - q;
    const double r2 = d.squaredNorm();
    if (r2 > kFarRatio * kFarRatio * node.radius * node.radius) {
      sum += node.dipole.dot(d) / (r2 * std::sqrt(r2));
    } else if (node.child[0] < 0) {
      sum += Direct(node.first, node.count, q);
    } else {
      stack[top++] = node.child[0];
      stack[top++] = node.child[1];
    }
  }
  return sum / kFourPi;
}

std::vector<double> PointAreas(const std::vector<double>& mean_neighbor_distance) {
  std::vector<double> areas(mean_neighbor_distance.size());
  for (size_t i = 0; i < areas.size(); ++i) {
    const double r = mean_neighbor_distance[i] / kMeanOfSixRoots;
    areas[i] = std::numbers::pi * r * r;
  }
  return areas;
}

}  // namespace meshseg::reconstruct_internal
