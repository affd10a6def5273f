// Hausdorff(): for every query point (vertices and face centroids of one
// mesh), the exact distance to the other mesh's nearest triangle. Candidate
// triangles come from a kd-tree (mesh/point_index.h) of the other's centroids: the
// nearest centroid's triangle bounds the distance by u, and any closer
// triangle has its centroid within u plus the largest centroid-corner
// distance.
#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "mesh/point_index.h"
#include "meshseg/voxel.h"

namespace meshseg {
namespace {

struct Triangles {
  std::vector<std::array<Eigen::Vector3d, 3>> corners;
  std::vector<Eigen::Vector3d> centroids;
  double reach = 0.0;  // largest centroid-corner distance
};

Triangles TrianglesOf(const TriMesh& mesh) {
  Triangles t;
  for (auto f : mesh.faces()) {
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for (auto v : mesh.fv_range(f)) c[k++] = ToEigen(mesh.point(v));
    const Eigen::Vector3d centroid = (c[0] + c[1] + c[2]) / 3.0;
    for (const auto& p : c) t.reach = std::max(t.reach, (p - centroid).norm());
    t.corners.push_back(c);
    t.centroids.push_back(centroid);
  }
  return t;
}

std::vector<Eigen::Vector3d> QueryPoints(const TriMesh& mesh) {
  std::vector<Eigen::Vector3d> q;
  for (auto v : mesh.vertices()) {
    if (!mesh.is_isolated(v)) q.push_back(ToEigen(mesh.point(v)));
  }
  for (auto f : mesh.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto v : mesh.fv_range(f)) c += ToEigen(mesh.point(v)) / 3.0;
    q.push_back(c);
  }
  return q;
}

// Max over `points` of the distance to the nearest triangle of `to`.
double OneSided(const std::vector<Eigen::Vector3d>& points, const Triangles& to) {
  if (to.centroids.empty()) return 0.0;
  const mesh_internal::PointIndex index(to.centroids);
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, points.size()), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double worst) {
        std::vector<std::pair<uint32_t, double>> found;
        for (size_t i = r.begin(); i < r.end(); ++i) {
          const Eigen::Vector3d& p = points[i];
          const auto& c = to.corners[index.Closest(p)];
          double best = SquaredDistanceToTriangle(p, c[0], c[1], c[2]);
          const double radius = std::sqrt(best) + to.reach;
          index.WithinRadius(p, radius, &found);
          for (const auto& [t, unused] : found) {
            const auto& tc = to.corners[t];
            best = std::min(best, SquaredDistanceToTriangle(p, tc[0], tc[1], tc[2]));
          }
          worst = std::max(worst, std::sqrt(best));
        }
        return worst;
      },
      [](double a, double b) { return std::max(a, b); });
}

}  // namespace

double SquaredDistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // Ericson, Real-Time Collision Detection 5.1.5: closest point by Voronoi regions.
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (ap - ab * (d1 / (d1 - d3))).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (ap - ac * (d2 / (d2 - d6))).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return (bp - (c - b) * w).squaredNorm();
  }
  const double denom = 1.0 / (va + vb + vc);
  const Eigen::Vector3d q = a + ab * (vb * denom) + ac * (vc * denom);
  return (p - q).squaredNorm();
}

HausdorffDistance Hausdorff(const TriMesh& a, const TriMesh& b) {
  HausdorffDistance h;
  h.input_to_output = OneSided(QueryPoints(a), TrianglesOf(b));
  h.output_to_input = OneSided(QueryPoints(b), TrianglesOf(a));
  return h;
}

}  // namespace meshseg
