#include "pipeline/inner_points.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "meshseg/fit.h"
#include "pipeline/boundary_distance.h"
#include "pipeline/refit_regions.h"

namespace meshseg::pipeline_internal {
namespace {

// Per region id (below `count`): the ids of the regions whose faces share
// an edge with its faces.
std::vector<std::vector<int>> NeighbourRegions(const TriMesh& mesh,
                                               std::span<const int> face_labels,
                                               std::size_t count) {
  std::vector<std::vector<int>> neighbours(count);
  const auto add = [&](int a, int b) {
    if (a < 0 || b < 0 || a == b || a >= static_cast<int>(count) || b >= static_cast<int>(count)) {
      return;
    }
    if (std::find(neighbours[a].begin(), neighbours[a].end(), b) == neighbours[a].end()) {
      neighbours[a].push_back(b);
    }
  };
  for (const auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const int a = face_labels[mesh.face_handle(mesh.halfedge_handle(e, 0)).idx()];
    const int b = face_labels[mesh.face_handle(mesh.halfedge_handle(e, 1)).idx()];
    add(a, b);
    add(b, a);
  }
  return neighbours;
}

}  // namespace

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
  std::vector<SharedSurface> trial_surfaces = *surfaces;
  RefitToPoints(inner, params.distance_tolerance, &decided);
  RetypeToPoints(inner, params.noise, &decided, &trial_surfaces, RetypeTo::kCurved);
  // A type decided on the inner points must still explain the region's
  // band points, which its own type fits: the ambiguous points it leaves
  // out must lie on a neighbour's surface (they were the neighbour's, as on
  // a chamfer whose region held the crease bands beyond both its edges).
  // Where they lie on neither, they are the region's own and refute it (a
  // torus round whose inner third a cone fits at the noise).
  const std::vector<std::vector<int>> neighbours = NeighbourRegions(mesh, face_labels, inner.size());
  std::vector<SurfaceType> original_type(inner.size(), SurfaceType::kPlane);
  for (std::size_t i = 0; i < regions->size(); ++i) {
    const Region& region = (*regions)[i];
    original_type[region.id] = region.type;
    if (decided[i].type == region.type) {
      inner[region.id].clear();
      continue;
    }
    std::size_t unexplained = 0;
    for (const Eigen::Vector3d& p : points_of_region[region.id]) {
      if (within_band(decided[i], p)) continue;
      bool on_neighbour = false;
      for (const int n : neighbours[region.id]) {
        on_neighbour = on_neighbour || (by_id[n] != nullptr && within_band(*by_id[n], p));
      }
      unexplained += !on_neighbour;
    }
    if (static_cast<double>(unexplained) >
        kMaxUnexplainedShare * static_cast<double>(points_of_region[region.id].size())) {
      inner[region.id].clear();
    }
  }
  // The decision replayed on the regions themselves for those whose new
  // type explains their points (the same inputs give the same decision).
  RefitToPoints(inner, params.distance_tolerance, regions);
  RetypeToPoints(inner, params.noise, regions, surfaces, RetypeTo::kCurved);
  std::vector<uint8_t> retyped(points_of_region.size(), 0);
  int inner_changed = 0;
  for (const Region& region : *regions) {
    if (inner[region.id].empty() || region.type == original_type[region.id]) continue;
    retyped[region.id] = 1;
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
