#include "reconstruct/seen_planes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

namespace meshseg::reconstruct_internal {
namespace {

// Candidate cap planes: through loop vertices a third (and a quarter and a
// half) of the loop apart, starting at this many evenly spread vertices.
constexpr int kCapCandidates = 64;
// A cap plane's normal is within this of the patch's mean normal (cosine).
constexpr double kMinCapCosine = 0.7;
// Loop vertices within this many mean edge lengths of a cap plane lie on it:
// the seen surfaces end within about a spacing of the unseen face.
constexpr double kCapBandEdges = 1.0;
// Least-squares refits of the chosen cap plane.
constexpr int kCapRefits = 2;
// Refit vertices span a plane when their second spread is at least this
// fraction of their first (else they lie along one edge of the hole).
constexpr double kMinSpreadRatio = 0.1;
// Tangent planes looked at per loop at most (the work is free vertices ×
// planes).
constexpr size_t kMaxPlanes = 1024;
// A point is outside a plane when it is more than this many mean edge lengths
// beyond it: room for the noise of the normals, which the planes carry across
// the hole.
constexpr double kSlackEdges = 2.0;

// The cap plane (unit outward normal, offset): of the planes through three
// loop vertices, within kMinCapCosine of `mean_normal` and with fewer loop
// vertices beyond it than on it, the one the most loop vertices lie
// on (weighted by how near, Torr & Zisserman 2000, MSAC), refitted to them
// by least squares. False when there is none.
bool CapPlane(const std::vector<Eigen::Vector3d>& loop, const Eigen::Vector3d& mean_normal,
              double band, Eigen::Vector3d* normal, double* offset) {
  const size_t n = loop.size();
  double best = 0.0;
  for (int c = 0; c < kCapCandidates; ++c) {
    const size_t i = c * n / kCapCandidates;
    for (const auto [a, b] : {std::pair<size_t, size_t>{n / 3, 2 * n / 3}, {n / 4, n / 2}}) {
      Eigen::Vector3d m = (loop[(i + a) % n] - loop[i]).cross(loop[(i + b) % n] - loop[i]);
      if (!(m.norm() > 0)) continue;
      m.normalize();
      if (m.dot(mean_normal) < 0) m = -m;
      if (m.dot(mean_normal) < kMinCapCosine) continue;
      const double d = m.dot(loop[i]);
      double on = 0.0;  // the vertices on it, each by 1 - (height / band)² (MSAC)
      size_t beyond = 0, within = 0;
      for (const Eigen::Vector3d& p : loop) {
        const double h = (m.dot(p) - d) / band;
        on += std::max(0.0, 1.0 - h * h);
        beyond += h > 1.0;
        within += std::abs(h) <= 1.0;
      }
      // The unseen face's rim lies on its plane and a fold hangs off a part
      // of that rim: the loop lies on the cap more than beyond it.
      if (beyond >= within || on <= best) {
        continue;
      }
      best = on;
      *normal = m;
      *offset = d;
    }
  }
  if (!(best > 0)) return false;
  // Least squares to the vertices on it, twice as near: on a scan the ends
  // of the seen surfaces scatter by about a spacing.
  std::vector<Eigen::Vector3d> on_plane;
  for (int round = 0; round < kCapRefits; ++round) {
    on_plane.clear();
    for (const Eigen::Vector3d& p : loop) {
      if (std::abs(normal->dot(p) - *offset) <= 0.5 * band) on_plane.push_back(p);
    }
    if (on_plane.size() < 3) break;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : on_plane) mean += p;
    mean /= static_cast<double>(on_plane.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : on_plane) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // ascending
    Eigen::Vector3d fitted = eig.eigenvectors().col(0);
    if (fitted.dot(*normal) < 0) fitted = -fitted;
    // Vertices along one line leave the normal free about it.
    if (eig.eigenvalues()(1) >= kMinSpreadRatio * kMinSpreadRatio * eig.eigenvalues()(2) &&
        fitted.dot(mean_normal) >= kMinCapCosine) {
      *normal = fitted;
    }
    *offset = normal->dot(mean);
  }
  return true;
}

}  // namespace

double LoopPerimeter(const std::vector<Eigen::Vector3d>& loop) {
  double sum = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) sum += (loop[(k + 1) % loop.size()] - loop[k]).norm();
  return sum;
}

bool SeenCapPlane(const std::vector<Eigen::Vector3d>& loop, const Eigen::Vector3d& mean_normal,
                  Eigen::Vector3d* normal, double* offset) {
  if (loop.size() < 3 || !(mean_normal.norm() > 0)) return false;
  const double edge = LoopPerimeter(loop) / static_cast<double>(loop.size());
  return CapPlane(loop, mean_normal.normalized(), kCapBandEdges * edge, normal, offset);
}

bool BendOntoSeenPlanes(const std::vector<Eigen::Vector3d>& loop,
                        const std::vector<Eigen::Vector3d>& normals,
                        const Eigen::Vector3d& patch_normal,
                        std::vector<Eigen::Vector3d>* free_vertices) {
  if (loop.size() < 3 || free_vertices->empty() || !(patch_normal.norm() > 0)) return false;
  const double edge = LoopPerimeter(loop) / static_cast<double>(loop.size());
  Eigen::Vector3d cap;
  double offset = 0.0;
  if (!CapPlane(loop, patch_normal.normalized(), kCapBandEdges * edge, &cap, &offset)) return false;
  // A plane that cuts off more than kMaxOutsideFraction of the loop is not a
  // face of the hull: a fold of the seen surface at the border, or, when
  // many are, a hole that is not convex. On a long loop every stride-th
  // tangent plane stands for its neighbours.
  const size_t stride = (loop.size() + kMaxPlanes - 1) / kMaxPlanes;
  std::vector<uint8_t> face(loop.size(), 0);
  size_t planes = 0, cutting = 0;
  for (size_t k = 0; k < loop.size(); k += stride) {
    if (!(normals[k].squaredNorm() > 0.5)) continue;  // no tangent plane there
    ++planes;
    size_t cut = 0;
    for (const Eigen::Vector3d& p : loop) cut += normals[k].dot(loop[k] - p) < -kSlackEdges * edge;
    if (static_cast<double>(cut) <= kMaxOutsideFraction * static_cast<double>(loop.size())) {
      face[k] = 1;
    } else {
      ++cutting;
    }
  }
  if (static_cast<double>(cutting) > kMaxCuttingFraction * static_cast<double>(planes)) {
    return false;
  }
  // Each free vertex goes onto the plane it is nearest to inside the hull.
  std::vector<Eigen::Vector3d> moved(*free_vertices);
  size_t outside = 0;
  for (Eigen::Vector3d& x : moved) {
    double least = offset - cap.dot(x);
    Eigen::Vector3d normal = cap;
    bool onto_cap = true;
    for (size_t k = 0; k < loop.size(); k += stride) {
      if (!face[k]) continue;
      const double clearance = normals[k].dot(loop[k] - x);
      if (clearance < least) {
        least = clearance;
        normal = normals[k];
        onto_cap = false;
      }
    }
    // Outwards onto any plane; inwards onto the cap plane only, which is
    // fitted to the loop's far run, and by no more than the slack: a tangent
    // plane carried across the hole is as near the surface as its noise
    // tells, and a vertex farther out is not explained by noise at all.
    if (least < -kSlackEdges * edge) {
      ++outside;
    } else if (least > 0 || onto_cap) {
      x += least * normal;
    }
  }
  if (static_cast<double>(outside) > kMaxOutsideFraction * static_cast<double>(moved.size())) {
    return false;
  }
  *free_vertices = std::move(moved);
  return true;
}

}  // namespace meshseg::reconstruct_internal
