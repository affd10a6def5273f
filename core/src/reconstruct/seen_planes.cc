#include "reconstruct/seen_planes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>

namespace meshseg::reconstruct_internal {
namespace {

// The cap plane is fitted around this quantile of the loop's heights along
// its normal: the farthest vertices but for stray ones (folds at the border).
constexpr double kCapQuantile = 0.9;
// Loop vertices within this many mean edge lengths of that quantile are the
// ones it is fitted to.
constexpr double kCapBandEdges = 2.0;
// Refits of the cap plane; each moves it onto the vertices the last one found.
constexpr int kCapRefits = 3;
// The refit vertices span a plane when their second spread is at least this
// fraction of their first (else they lie along one edge of the hole).
constexpr double kMinSpreadRatio = 0.1;
// A refit may turn the cap's normal by at most this much (cosine).
constexpr double kMinRefitCosine = 0.7;
// A point is outside a plane when it is more than this many mean edge lengths
// beyond it: room for the noise of the normals, which the planes carry across
// the hole.
constexpr double kSlackEdges = 2.0;

double Quantile(std::vector<double> values, double q) {
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

bool BendOntoSeenPlanes(const std::vector<Eigen::Vector3d>& loop,
                        const std::vector<Eigen::Vector3d>& normals,
                        const Eigen::Vector3d& patch_normal,
                        std::vector<Eigen::Vector3d>* free_vertices) {
  if (loop.size() < 3 || free_vertices->empty() || !(patch_normal.norm() > 0)) return false;
  double edge = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) edge += (loop[(k + 1) % loop.size()] - loop[k]).norm();
  edge /= static_cast<double>(loop.size());
  Eigen::Vector3d cap = patch_normal.normalized();
  std::vector<double> heights(loop.size());
  // The cap plane: fitted to the loop vertices near the quantile (the seen
  // surfaces' ends next to the unseen face, whichever way they run).
  double offset = 0.0;
  for (int round = 0; round <= kCapRefits; ++round) {
    for (size_t k = 0; k < loop.size(); ++k) heights[k] = cap.dot(loop[k]);
    const double reference = Quantile(heights, kCapQuantile);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int n = 0;
    for (size_t k = 0; k < loop.size(); ++k) {
      if (std::abs(heights[k] - reference) > kCapBandEdges * edge) continue;
      mean += loop[k];
      ++n;
    }
    mean /= n;  // n >= 1: the reference vertex itself
    offset = cap.dot(mean);
    if (round == kCapRefits || n < 3) break;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (size_t k = 0; k < loop.size(); ++k) {
      if (std::abs(heights[k] - reference) > kCapBandEdges * edge) continue;
      cov += (loop[k] - mean) * (loop[k] - mean).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // ascending
    if (!(eig.eigenvalues()(1) >= kMinSpreadRatio * kMinSpreadRatio * eig.eigenvalues()(2))) break;
    Eigen::Vector3d fitted = eig.eigenvectors().col(0);
    if (fitted.dot(cap) < 0) fitted = -fitted;
    if (fitted.dot(cap) < kMinRefitCosine) break;
    cap = fitted;
    offset = cap.dot(mean);
  }
  // A plane that cuts off more than kMaxOutsideFraction of the loop is not a
  // face of the hull: a fold of the seen surface at the border, or, when
  // many are, a hole that is not convex.
  std::vector<uint8_t> face(loop.size(), 1);
  size_t cutting = 0;
  for (size_t k = 0; k < loop.size(); ++k) {
    size_t cut = 0;
    for (const Eigen::Vector3d& p : loop) cut += normals[k].dot(loop[k] - p) < -kSlackEdges * edge;
    if (static_cast<double>(cut) <= kMaxOutsideFraction * static_cast<double>(loop.size())) continue;
    face[k] = 0;
    ++cutting;
  }
  if (static_cast<double>(cutting) > kMaxCuttingFraction * static_cast<double>(loop.size())) {
    return false;
  }
  // Each free vertex goes onto the plane it is nearest to inside the hull.
  std::vector<Eigen::Vector3d> moved(*free_vertices);
  size_t outside = 0;
  for (Eigen::Vector3d& x : moved) {
    double least = offset - cap.dot(x);
    Eigen::Vector3d normal = cap;
    for (size_t k = 0; k < loop.size(); ++k) {
      if (!face[k]) continue;
      const double clearance = normals[k].dot(loop[k] - x);
      if (clearance < least) {
        least = clearance;
        normal = normals[k];
      }
    }
    if (least < -kSlackEdges * edge) ++outside;
    x += least * normal;
  }
  if (static_cast<double>(outside) > kMaxOutsideFraction * static_cast<double>(moved.size())) {
    return false;
  }
  *free_vertices = std::move(moved);
  return true;
}

}  // namespace meshseg::reconstruct_internal

