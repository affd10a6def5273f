// How close a reconstructed surface is to the truth, and whether it is a
// closed manifold: the numbers issue 38 states (accuracy and completeness
// quantiles in point spacings, open and non-manifold edges, handles). Shared
// by the reconstruct tests and bench/reconstruct/reconstruct_eval.
//
// accuracy:     distances from area samples of the reconstruction to the truth;
// completeness: distances from area samples of the truth to the reconstruction
//               (of its visible part only, for scans: truth samples within a
//               few spacings of a scan point).
// Distances are exact point-to-triangle distances.
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_SURFACE_METRICS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_SURFACE_METRICS_H_

#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/voxel.h"
#include "mesh/point_index.h"

namespace meshseg::test {

// Distance from p to triangle abc (exact; meshseg/voxel.h).
inline double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return std::sqrt(SquaredDistanceToTriangle(p, a, b, c));
}

using Triangle = std::array<Eigen::Vector3d, 3>;

inline std::vector<Triangle> Triangles(const TriMesh& m) {
  std::vector<Triangle> out;
  out.reserve(m.n_faces());
  for (const auto f : m.faces()) {
    Triangle t;
    int i = 0;
    for (const auto v : f.vertices()) t[i++] = ToEigen(m.point(v));
    out.push_back(t);
  }
  return out;
}

// Exact distance queries to a set of triangles: the triangles' centroids in a
// k-d tree; a query takes every triangle whose centroid lies within the best
// distance so far plus the largest centroid-to-corner radius. Triangles much
// larger than the typical one (CAD truth meshes) are checked one by one.
class SurfaceDistance {
 public:
  explicit SurfaceDistance(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
    std::vector<double> radius(triangles_.size());
    for (size_t t = 0; t < triangles_.size(); ++t) {
      const Eigen::Vector3d c = (triangles_[t][0] + triangles_[t][1] + triangles_[t][2]) / 3.0;
      double r = 0.0;
      for (const auto& p : triangles_[t]) r = std::max(r, (p - c).norm());
      radius[t] = r;
    }
    std::vector<double> sorted = radius;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double large = 4.0 * (sorted.empty() ? 0.0 : sorted[sorted.size() / 2]);
    for (size_t t = 0; t < triangles_.size(); ++t) {
      if (radius[t] > large) {
        large_.push_back(static_cast<uint32_t>(t));
        continue;
      }
      small_.push_back(static_cast<uint32_t>(t));
      centroids_.push_back((triangles_[t][0] + triangles_[t][1] + triangles_[t][2]) / 3.0);
      max_radius_ = std::max(max_radius_, radius[t]);
    }
    index_ = std::make_unique<mesh_internal::PointIndex>(centroids_);
  }

  double operator()(const Eigen::Vector3d& p) const {
    double best = std::numeric_limits<double>::infinity();
    const auto distance = [&](uint32_t t) {
      return PointTriangleDistance(p, triangles_[t][0], triangles_[t][1], triangles_[t][2]);
    };
    for (const uint32_t t : large_) best = std::min(best, distance(t));
    if (centroids_.empty()) return best;
    std::vector<uint32_t> nearest;
    std::vector<double> d2;
    index_->Nearest(p, 1, &nearest, &d2);
    best = std::min(best, distance(small_[nearest[0]]));
    std::vector<std::pair<uint32_t, double>> found;
    index_->WithinRadius(p, best + max_radius_, &found);
    for (const auto& [j, unused] : found) best = std::min(best, distance(small_[j]));
    return best;
  }

 private:
  std::vector<Triangle> triangles_;
  std::vector<uint32_t> small_, large_;
  std::vector<Eigen::Vector3d> centroids_;
  double max_radius_ = 0.0;
  std::unique_ptr<mesh_internal::PointIndex> index_;
};

// `count` points uniform by area on `triangles` (fixed seed).
inline std::vector<Eigen::Vector3d> AreaSamples(const std::vector<Triangle>& triangles, int count,
                                                unsigned seed = 5) {
  std::vector<double> area;
  for (const auto& t : triangles) area.push_back(0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm());
  std::mt19937 rng(seed);
  std::discrete_distribution<size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  out.reserve(count);
  for (int i = 0; i < count; ++i) {
    const auto& t = triangles[pick(rng)];
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    out.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
  }
  return out;
}

// Sorted distances from `points` to `surface`, in parallel.
inline std::vector<double> SortedDistances(const std::vector<Eigen::Vector3d>& points,
                                           const SurfaceDistance& surface) {
  std::vector<double> d(points.size());
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t i) { d[i] = surface(points[i]); });
  std::sort(d.begin(), d.end());
  return d;
}

inline double Quantile(const std::vector<double>& sorted, double q) {
  return sorted.empty() ? 0.0 : sorted[static_cast<size_t>(q * (sorted.size() - 1))];
}

// Median over points of the distance to the nearest other point: the
// cloud's median point spacing, "sp" of issue 38. (ReconstructStats::
// point_spacing, the median mean distance to 6 neighbours, is about twice it
// on a uniform sample.)
inline double MedianSpacing(const std::vector<Eigen::Vector3d>& points) {
  const mesh_internal::PointIndex index(points);
  std::vector<double> nearest(points.size());
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t i) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    index.Nearest(points[i], 2, &idx, &d2);
    nearest[i] = d2.size() < 2 ? 0.0 : std::sqrt(d2[1]);
  });
  auto middle = nearest.begin() + nearest.size() / 2;
  std::nth_element(nearest.begin(), middle, nearest.end());
  return *middle;
}

// Sum of the genera of the closed components of `m` (V − E + F = 2 − 2g per
// component), or -1 if any edge is open.
inline int64_t TotalGenus(const TriMesh& m) {
  int64_t components = 0;
  std::vector<int> seen(m.n_vertices(), 0);
  for (const auto v : m.vertices()) {
    if (seen[v.idx()] || m.is_isolated(v)) continue;
    ++components;
    std::vector<OpenMesh::SmartVertexHandle> stack = {v};
    seen[v.idx()] = 1;
    while (!stack.empty()) {
      const auto cur = stack.back();
      stack.pop_back();
      for (const auto nb : cur.vertices()) {
        if (!seen[nb.idx()]) seen[nb.idx()] = 1, stack.push_back(nb);
      }
    }
  }
  for (const auto e : m.edges()) {
    if (m.is_boundary(e)) return -1;
  }
  int64_t used = 0;
  for (const auto v : m.vertices()) used += !m.is_isolated(v);
  const int64_t chi = used - static_cast<int64_t>(m.n_edges()) + static_cast<int64_t>(m.n_faces());
  return (2 * components - chi) / 2;
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_SURFACE_METRICS_H_
