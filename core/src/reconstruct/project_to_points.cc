#include "reconstruct/project_to_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <variant>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/fit.h"

namespace meshseg::reconstruct_internal {
namespace {

// Reusable per-thread inputs of the plane fit.
struct PlaneScratch {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
};

// One projection step of x onto the Gaussian-weighted least-squares plane
// (FitPlane) of its neighbourhood. `found` holds (point index, squared
// distance to x).
Eigen::Vector3d OntoLocalPlane(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::pair<uint32_t, double>>& found, double sigma2,
                               PlaneScratch* scratch) {
  scratch->points.clear();
  scratch->weights.clear();
  for (const auto& [j, d2] : found) {
    scratch->points.push_back(points[j]);
    scratch->weights.push_back(std::exp(-d2 / sigma2));
  }
  const FitResult fit =
      FitPlane({.points = scratch->points, .normals = {}, .weights = scratch->weights});
  if (!fit.ok()) return x;
  const Plane& plane = std::get<Plane>(fit.surface);
  return x - plane.normal.dot(x - plane.point) * plane.normal;
}

}  // namespace

std::vector<int> ProjectToPoints(const std::vector<Eigen::Vector3d>& points,
                                 const mesh_internal::PointIndex& index, double radius,
                                 int iterations, TriMesh* mesh) {
  const double sigma2 = radius * radius / 4.0;
  std::vector<uint8_t> left(mesh->n_vertices(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh->n_vertices()), [&](const auto& range) {
    std::vector<std::pair<uint32_t, double>> found;
    std::vector<uint32_t> nearest;
    std::vector<double> nearest_d2;
    PlaneScratch scratch;
    for (size_t v = range.begin(); v != range.end(); ++v) {
      const TriMesh::VertexHandle vh(static_cast<int>(v));
      Eigen::Vector3d x = ToEigen(mesh->point(vh));
      for (int step = 0; step < iterations; ++step) {
        index.WithinRadiusUnordered(x, radius, &found);
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
        x = OntoLocalPlane(x, points, found, widened, &scratch);
      }
      mesh->set_point(vh, TriMesh::Point(x[0], x[1], x[2]));
    }
  });
  std::vector<int> out;
  for (size_t v = 0; v < left.size(); ++v) {
    if (left[v]) out.push_back(static_cast<int>(v));
  }
  return out;
}

}  // namespace meshseg::reconstruct_internal
