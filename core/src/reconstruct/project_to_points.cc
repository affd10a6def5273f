#include "reconstruct/project_to_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <variant>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "meshseg/fit.h"

namespace meshseg::reconstruct_internal {
namespace {

// Reusable per-thread inputs of the plane fit.
struct PlaneScratch {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> weights;
};

// One projection step of x onto the Gaussian-weighted least-squares plane
// (FitPlane) of its neighbourhood, or onto the two planes of a crease there
// (when `normals` are given); sets *crease to the crease or resets it.
// `found` holds (point index, squared distance to x).
Eigen::Vector3d OntoLocalSurface(const Eigen::Vector3d& x,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals,
                                 const std::vector<std::pair<uint32_t, double>>& found,
                                 double sigma2, double noise, PlaneScratch* scratch,
                                 std::optional<Crease>* crease) {
  scratch->points.clear();
  scratch->normals.clear();
  scratch->weights.clear();
  for (const auto& [j, d2] : found) {
    scratch->points.push_back(points[j]);
    scratch->weights.push_back(std::exp(-d2 / sigma2));
    if (!normals.empty()) scratch->normals.push_back(normals[j]);
  }
  crease->reset();
  if (!normals.empty()) {
    *crease = FitCrease(scratch->points, scratch->normals, scratch->weights, noise);
    if (*crease) return (*crease)->Nearest(x);
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
                                 int iterations, TriMesh* mesh,
                                 const std::vector<Eigen::Vector3d>& normals, double noise,
                                 std::vector<std::pair<int, Crease>>* creases,
                                 const std::vector<int>* only) {
  const double sigma2 = radius * radius / 4.0;
  const size_t count = only ? only->size() : mesh->n_vertices();
  std::vector<uint8_t> left(count, 0);
  tbb::enumerable_thread_specific<std::vector<std::pair<int, Crease>>> found_creases;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count), [&](const auto& range) {
    std::vector<std::pair<uint32_t, double>> found;
    std::vector<uint32_t> nearest;
    std::vector<double> nearest_d2;
    PlaneScratch scratch;
    std::optional<Crease> crease;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const int v = only ? (*only)[i] : static_cast<int>(i);
      const TriMesh::VertexHandle vh(v);
      Eigen::Vector3d x = ToEigen(mesh->point(vh));
      crease.reset();
      for (int step = 0; step < iterations; ++step) {
        index.WithinRadiusUnordered(x, radius, &found);
        double widened = sigma2;
        if (found.size() < kMinProjectionPoints) {
          index.Nearest(x, kMinProjectionPoints, &nearest, &nearest_d2);
          const double reach = kFallbackReach * radius;
          if (nearest.size() < kMinProjectionPoints || nearest_d2.back() > reach * reach) {
            left[i] = step == 0;
            break;
          }
          found.clear();
          for (size_t k = 0; k < nearest.size(); ++k) found.emplace_back(nearest[k], nearest_d2[k]);
          widened = nearest_d2.back() / 4.0;
        }
        x = OntoLocalSurface(x, points, normals, found, widened, noise, &scratch, &crease);
      }
      mesh->set_point(vh, TriMesh::Point(x[0], x[1], x[2]));
      if (crease && creases) found_creases.local().emplace_back(v, *crease);
    }
  });
  if (creases) {
    creases->clear();
    for (const auto& part : found_creases)
      creases->insert(creases->end(), part.begin(), part.end());
    std::sort(creases->begin(), creases->end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  std::vector<int> out;
  for (size_t i = 0; i < left.size(); ++i) {
    if (left[i]) out.push_back(only ? (*only)[i] : static_cast<int>(i));
  }
  return out;
}

}  // namespace meshseg::reconstruct_internal
