#include "pipeline/inner_points.h"

#include <cmath>
#include <cstddef>
#include <utility>

#include "meshseg/fit.h"
#include "pipeline/boundary_distance.h"
#include "pipeline/refit_regions.h"

namespace meshseg::pipeline_internal {

int RetypeOnInnerPoints(const TriMesh& mesh, std::span<const int> face_labels,
                        std::span<const Eigen::Vector3d> cloud,
                        std::span<const int> nearest_label,
                        std::span<const uint32_t> nearest_vertex, const InnerPointParams& params,
                        std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                        std::vector<Region>* regions, std::vector<SharedSurface>* surfaces) {
  // First on all its band points, as before: a plane may take over there.
  int changed = RetypeToPoints(points_of_region, params.noise, regions, surfaces);
  // The region of each id (the labels and points_of_region go by id).
  std::vector<const Region*> by_id(points_of_region.size(), nullptr);
  for (const Region& region : *regions) by_id[region.id] = &region;
  const auto within_band = [&](const Region& region, const Eigen::Vector3d& p) {
    return std::abs(SignedDistance(region.surface, p)) <= params.band;
  };
  // Only whether a vertex lies inner_distance or farther from a boundary
  // matters (those farther stay at infinity).
  const double inner_distance = kAmbiguousSpacings * params.spacing;
  const std::vector<double> boundary = VertexBoundaryDistance(mesh, face_labels, inner_distance);
  // Planes, quadrics and freeform regions are not retyped on points.
  const auto curved = [](const Region& region) {
    return region.type != SurfaceType::kPlane && region.type != SurfaceType::kQuadric &&
           region.type != SurfaceType::kFreeform;
  };
  std::vector<std::vector<Eigen::Vector3d>> inner(points_of_region.size());
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    const int r = nearest_label[k];
    if (r < 0 || by_id[r] == nullptr || !curved(*by_id[r]) ||
        !(boundary[nearest_vertex[k]] >= inner_distance)) {
      continue;
    }
    if (within_band(*by_id[r], cloud[k])) inner[r].push_back(cloud[k]);
  }
  // A region with fewer inner points than kMinRetypePoints is about as
  // narrow as its ambiguous bands: its band points decided.
  for (std::vector<Eigen::Vector3d>& points : inner) {
    if (points.size() < kMinRetypePoints) points.clear();
  }
  // Then on its inner points, to a curved type only: a plane fits any strip
  // of a curved face narrow enough within the noise, and the inner points of
  // a narrow region are such a strip (a fillet's inner third). The decision
  // is made on copies: a region that keeps its type keeps its surface
  // fitted to all its band points.
  std::vector<Region> decided = *regions;
  RefitToPoints(inner, params.distance_tolerance, &decided);
  RetypeToPoints(inner, params.noise, &decided, surfaces, RetypeTo::kCurved);
  std::vector<uint8_t> retyped(points_of_region.size(), 0);
  int inner_changed = 0;
  for (std::size_t i = 0; i < regions->size(); ++i) {
    if (decided[i].type == (*regions)[i].type) continue;
    (*regions)[i] = decided[i];
    retyped[decided[i].id] = 1;
    ++inner_changed;
  }
  if (inner_changed == 0) return changed;
  // A retyped region takes back every point of its nearest faces within the
  // band of its new surface and is refitted on them.
  std::vector<std::vector<Eigen::Vector3d>> readmitted(points_of_region.size());
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    const int r = nearest_label[k];
    if (r >= 0 && retyped[r] && within_band(*by_id[r], cloud[k])) {
      readmitted[r].push_back(cloud[k]);
    }
  }
  RefitToPoints(readmitted, params.distance_tolerance, regions);
  for (const Region& region : *regions) {
    if (!retyped[region.id]) continue;
    // RetypeToPoints gave it a surface of its own (a cone that RefitToPoints
    // made a cylinder keeps the one it shares, as RefitToPoints leaves it).
    if (region.surface_id < 0 || region.surface_id >= static_cast<int>(surfaces->size())) continue;
    SharedSurface& own = (*surfaces)[region.surface_id];
    if (own.regions.size() != 1 || own.regions[0] != region.id) continue;
    own.type = region.type;
    own.surface = region.surface;
    own.rms_distance = region.rms_distance;
    own.max_distance = region.max_distance;
  }
  return changed + inner_changed;
}

}  // namespace meshseg::pipeline_internal
