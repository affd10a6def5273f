#include "reconstruct/project_to_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// One projection step of x onto the weighted plane of its neighbourhood.
// `found` holds (point index, squared distance to x).
Eigen::Vector3d OntoLocalPlane(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::pair<uint32_t, double>>& found,
                               double sigma2) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  for (const auto& [j, d2] : found) {
    const double w = std::exp(-d2 / sigma2);
    centroid += w * points[j];
    weight_sum += w;
  }
  if (!(weight_sum > 0.0)) return x;
  centroid /= weight_sum;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& [j, d2] : found) {
    const Eigen::Vector3d d = points[j] - centroid;
    covariance += std::exp(-d2 / sigma2) * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  const Eigen::Vector3d normal = eig.eigenvectors().col(0);
  return x - normal.dot(x - centroid) * normal;
}

}  // namespace

std::vector<int> ProjectToPoints(const std::vector<Eigen::Vector3d>& points,
                                 const PointIndex& index, double radius, int iterations,
                                 TriMesh* mesh) {
  const double sigma2 = radius * radius / 4.0;
  std::vector<uint8_t> left(mesh->n_vertices(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh->n_vertices()), [&](const auto& range) {
    std::vector<std::pair<uint32_t, double>> found;
    std::vector<uint32_t> nearest;
    std::vector<double> nearest_d2;
    for (size_t v = range.begin(); v != range.end(); ++v) {
      const TriMesh::VertexHandle vh(static_cast<int>(v));
      Eigen::Vector3d x = ToEigen(mesh->point(vh));
      for (int step = 0; step < iterations; ++step) {
        index.WithinRadius(x, radius, &found);
        double widened = sigma2;
        if (found.size() < kMinProjectionPoints) {
          index.Nearest(x, kMinProjectionPoints, &nearest, &nearest_d2);
          const double reach = kFallbackReach * radius;
          if (nearest.size() < kMinProjectionPoints || nearest_d2.back() > reach * reach) {
            left[v] = step == 0;
            break;
          }
          found.clear();
          for (size_t k = 0; k < nearest.size(); ++k) found.emplace_back(nearest[k], nearest_d2[k]);
          widened = nearest_d2.back() / 4.0;
        }
        x = OntoLocalPlane(x, points, found, widened);
      }
      mesh->set_point(vh, TriMesh::Point(x[0], x[1], x[2]));
    }
  });
  mesh->update_normals();
  std::vector<int> out;
  for (size_t v = 0; v < left.size(); ++v) {
    if (left[v]) out.push_back(static_cast<int>(v));
  }
  return out;
}

}  // namespace meshseg::reconstruct_internal
