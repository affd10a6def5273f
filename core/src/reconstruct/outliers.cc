#include "reconstruct/outliers.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// cos 60°: a normal farther than this from its neighbours' mean is wrong.
// Sharp edges (45°) and cube corners (54.7°) stay below it.
constexpr double kMinCos = 0.5;

}  // namespace

std::vector<uint8_t> OutlierFlags(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& normals,
                                  const mesh_internal::PointIndex& index,
                                  const std::vector<double>& spread, int k,
                                  double isolated_distance, double off_surface_distance) {
  std::vector<uint8_t> flags(points.size(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (!(spread[i] <= isolated_distance)) {
        flags[i] = 1;
        continue;
      }
      index.Nearest(points[i], k + 1, &idx, &d2);
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero();
      int count = 0;
      for (const uint32_t j : idx) {
        if (j == i) continue;
        mean += points[j];
        if (!normals.empty()) mean_normal += normals[j].normalized();
        ++count;
      }
      if (count < 3) continue;
      mean /= count;
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (const uint32_t j : idx) {
        if (j != i) cov += (points[j] - mean) * (points[j] - mean).transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
      const double off = std::abs(eig.eigenvectors().col(0).dot(points[i] - mean));
      const bool astray = !normals.empty() &&
                          normals[i].normalized().dot(mean_normal) < kMinCos * mean_normal.norm();
      flags[i] = off > off_surface_distance || astray ? 1 : 0;
    }
  });
  return flags;
}

std::vector<double> MeanNeighborDistances(const std::vector<Eigen::Vector3d>& points,
                                          const mesh_internal::PointIndex& index) {
  constexpr int kNeighbors = 6;
  std::vector<double> mean(points.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      index.Nearest(points[i], kNeighbors + 1, &idx, &d2);
      double sum = 0.0;
      for (size_t j = 1; j < d2.size(); ++j) sum += std::sqrt(d2[j]);
      mean[i] = d2.size() > 1 ? sum / static_cast<double>(d2.size() - 1) : 0.0;
    }
  });
  return mean;
}

}  // namespace meshseg::reconstruct_internal
