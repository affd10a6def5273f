#include "reconstruct/crease.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Rounds of assigning the points to the nearer plane and refitting.
constexpr int kResidualRounds = 2;

// A weighted least-squares plane: weighted centroid and the least-variance
// direction; `mean_square` is the weighted mean squared residual.
struct PlaneFit {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double mean_square = 0.0;
  double weight = 0.0;
  int count = 0;
};

// Fits the points whose `label` is `k` (all when k < 0) and turns the normal
// towards the sum of their normals (inward).
PlaneFit FitPlaneOf(const std::vector<Eigen::Vector3d>& at,
                    const std::vector<Eigen::Vector3d>& normal, const std::vector<double>& weight,
                    const std::vector<int>& label, int k) {
  PlaneFit fit;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), normal_sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < at.size(); ++i) {
    if (k >= 0 && label[i] != k) continue;
    sum += weight[i] * at[i];
    normal_sum += normal[i];
    fit.weight += weight[i];
    ++fit.count;
  }
  if (fit.count < 3 || !(fit.weight > 0)) return fit;
  fit.point = sum / fit.weight;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < at.size(); ++i) {
    if (k >= 0 && label[i] != k) continue;
    const Eigen::Vector3d d = at[i] - fit.point;
    cov.noalias() += weight[i] * d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(cov);
  fit.normal = eigen.eigenvectors().col(0).normalized();
  if (fit.normal.dot(normal_sum) < 0) fit.normal = -fit.normal;
  fit.mean_square = std::max(0.0, eigen.eigenvalues()[0]) / fit.weight;
  return fit;
}

}  // namespace

int Crease::Side(const Eigen::Vector3d& x) const {
  // On plane 0's part g0 = 0 and g1 ≥ 0 (convex) or ≤ 0 (concave).
  const double s = g(0, x) - g(1, x);
  return convex ? (s < 0 ? 0 : 1) : (s > 0 ? 0 : 1);
}

Eigen::Vector3d Crease::OntoLine(const Eigen::Vector3d& x) const {
  // x + α n0 + β n1 on both planes: the nearest such point to x.
  const double c = normal[0].dot(normal[1]);
  const double r0 = -g(0, x), r1 = -g(1, x);
  const double det = 1.0 - c * c;
  const double alpha = (r0 - c * r1) / det, beta = (r1 - c * r0) / det;
  return x + alpha * normal[0] + beta * normal[1];
}

Eigen::Vector3d Crease::Nearest(const Eigen::Vector3d& x) const {
  Eigen::Vector3d best = OntoLine(x);
  double best_d2 = (best - x).squaredNorm();
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d on = x - g(k, x) * normal[k];
    const double other = g(1 - k, on);
    if (convex ? other < 0 : other > 0) continue;  // beyond the crease
    const double d2 = (on - x).squaredNorm();
    if (d2 < best_d2) {
      best = on;
      best_d2 = d2;
    }
  }
  return best;
}

std::optional<Crease> FitCrease(const std::vector<Eigen::Vector3d>& at,
                                const std::vector<Eigen::Vector3d>& normal,
                                const std::vector<double>& weight, double noise) {
  const size_t n = at.size();
  if (n < 6) return std::nullopt;
  const double cos_min = std::cos(kMinCreaseAngleDeg * kPi / 180.0);
  const double cos_half = std::cos(0.5 * kMinCreaseAngleDeg * kPi / 180.0);
  // Do the normals split? The one farthest from the weighted mean seeds one
  // group, the one farthest from it the other.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) mean += weight[i] * normal[i];
  if (!(mean.norm() > 0)) return std::nullopt;
  mean.normalize();
  size_t far0 = 0;
  for (size_t i = 1; i < n; ++i) {
    if (normal[i].dot(mean) < normal[far0].dot(mean)) far0 = i;
  }
  if (normal[far0].dot(mean) > cos_half) return std::nullopt;
  size_t far1 = 0;
  for (size_t i = 1; i < n; ++i) {
    if (normal[i].dot(normal[far0]) < normal[far1].dot(normal[far0])) far1 = i;
  }
  Eigen::Vector3d seed[2] = {normal[far0], normal[far1]};
  std::vector<int> label(n);
  for (int round = 0; round < 2; ++round) {
    Eigen::Vector3d sum[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (size_t i = 0; i < n; ++i) {
      label[i] = normal[i].dot(seed[1]) > normal[i].dot(seed[0]);
      sum[label[i]] += normal[i];
    }
    for (int k = 0; k < 2; ++k) {
      if (!(sum[k].norm() > 0)) return std::nullopt;
      seed[k] = sum[k].normalized();
    }
  }
  // Then by position (k-planes): each point to the plane nearer to it; a
  // point by the crease whose estimated normal averages both sides goes to
  // the surface it lies on.
  PlaneFit planes[2];
  for (int round = 0;; ++round) {
    for (int k = 0; k < 2; ++k) {
      planes[k] = FitPlaneOf(at, normal, weight, label, k);
      if (planes[k].count < 3) return std::nullopt;
    }
    if (round == kResidualRounds) break;
    for (size_t i = 0; i < n; ++i) {
      const double d0 = std::abs(planes[0].normal.dot(at[i] - planes[0].point));
      const double d1 = std::abs(planes[1].normal.dot(at[i] - planes[1].point));
      label[i] = d1 < d0;
    }
  }
  // Planes at an angle, neither (nearly) parallel nor facing (two sides of a
  // thin wall): |sin| of the angle at least that of kMinCreaseAngleDeg.
  const double c = planes[0].normal.dot(planes[1].normal);
  if (std::abs(c) > cos_min) return std::nullopt;
  const PlaneFit one = FitPlaneOf(at, normal, weight, label, -1);
  const double two_mean_square =
      (planes[0].mean_square * planes[0].weight + planes[1].mean_square * planes[1].weight) /
      (planes[0].weight + planes[1].weight);
  const bool beyond_noise = one.mean_square > kPlaneNoiseFit * kPlaneNoiseFit * noise * noise;
  const bool explained =
      two_mean_square <= kCreaseResidualRatio * kCreaseResidualRatio * one.mean_square;
  if (!beyond_noise || !explained) return std::nullopt;
  Crease crease;
  for (int k = 0; k < 2; ++k) {
    crease.point[k] = planes[k].point;
    crease.normal[k] = planes[k].normal;
  }
  // Convex when each plane's points lie inside the other's half-space.
  crease.convex = crease.g(0, planes[1].point) + crease.g(1, planes[0].point) > 0;
  return crease;
}

}  // namespace meshseg::reconstruct_internal
