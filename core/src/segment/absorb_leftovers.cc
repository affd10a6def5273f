#include "segment/absorb_leftovers.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/decide_type.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

// ALGORITHMS.md S2 STB3 steps (1.0, 16°), (1.5, 24°), (2.0, 32°), ... from the base
// (0.5, 8°): multiples 2, 3, 4, ... of the base thresholds.
constexpr int kSteps = 5;
constexpr double kMaxAngleDeg = 80.0;
constexpr double kPi = 3.14159265358979323846;
constexpr int kNoPick = -1;
// Share of a region's vertices on a neighbour's surface that makes it a
// piece of that neighbour (LiesOnANeighbour). Measured at the releases:
// fragments of every type on the generated parts at sigma = 0.15 h (three
// noise draws) 0.44 to 1, strips of a round 0.95; a small plane disc on top
// of a conical frustum 0 at 1.5 times the part's voxel size without noise,
// 0.15 to 0.30 at 1.25 times and sigma = 0.15 h.
constexpr double kOnNeighbourShare = 1.0 / 3.0;
// A small face is flat: its plane meets its vertices within this many
// sigmas (rms). That plane disc at 1.25 h and sigma = 0.15 h: 0.99 to 1.29
// sigma; the rim fragments that pass the share above (at sigma = 0.05 h, on
// the 41-degree crease where a sphere cap of r 20 meets a cylinder of r 15:
// 30 and 37 vertices, 4 and 11 of them on a neighbour): 4.2 and 2.9 sigma.
constexpr double kFaceSigmas = 2.0;

// The thresholds of step `step` (0 to kSteps - 1).
Tolerance Stepped(const SegmentContext& c, int step) {
  const double scale = 2.0 + step;
  const double angle_deg = std::min(kMaxAngleDeg, c.angle_tolerance_deg * scale);
  return Tolerance{.distance = c.tolerance.distance * scale,
                   .cos_angle = std::cos(angle_deg * kPi / 180.0)};
}

// For every free vertex next to a region, the best neighbouring region it
// meets `tol` for (smallest distance), or any labelled neighbour if `tol`
// is null. Synchronous sweep: decisions use the labels before the sweep.
int Sweep(const SegmentContext& c, const std::vector<RegionState>& regions, const Tolerance* tol,
          std::vector<int>* labels) {
  const int n = c.vertex_count();
  std::vector<int> pick(n, kNoPick);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 1024), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if ((*labels)[v] != -1 || c.graph.Neighbors(v).empty()) continue;
      double best = std::numeric_limits<double>::infinity();
      for (const int j : c.graph.Neighbors(v)) {
        const int id = (*labels)[j];
        if (id < 0 || id == pick[v]) continue;
        const Projection pr = ProjectVertex(c, regions[id].surface, v);
        if (tol != nullptr && !Fits(c, v, pr, *tol)) continue;
        const double d = std::abs(pr.distance);
        if (d < best || (d == best && id < pick[v])) {
          best = d;
          pick[v] = id;
        }
      }
    }
  });
  int changed = 0;
  for (int v = 0; v < n; ++v) {
    if (pick[v] == kNoPick) continue;
    (*labels)[v] = pick[v];
    ++changed;
  }
  return changed;
}

// Free connected islands with no region at all become regions of their own.
void TypeIslands(const SegmentContext& c, std::vector<int>* labels,
                 std::vector<RegionState>* regions) {
  for (int s = 0; s < c.vertex_count(); ++s) {
    if ((*labels)[s] != -1 || c.graph.Neighbors(s).empty()) continue;
    const int id = static_cast<int>(regions->size());
    std::vector<int> island = {s};
    (*labels)[s] = id;
    for (std::size_t head = 0; head < island.size(); ++head) {
      for (const int j : c.graph.Neighbors(island[head])) {
        if ((*labels)[j] != -1) continue;
        (*labels)[j] = id;
        island.push_back(j);
      }
    }
    std::sort(island.begin(), island.end());
    TypedFit typed;
    if (auto plane = PlaneIfFits(c, island, c.tolerance)) {
      typed = *plane;
    } else {
      typed = DecideCurvedType(c, island, c.tolerance);
    }
    regions->push_back(RegionState{.type = typed.type,
                                   .surface = typed.fit.surface,
                                   .vertices = std::move(island),
                                   .alive = true});
  }
}

// True if kOnNeighbourShare of region `id`'s vertices meet the surface of
// a region beside it within the first step's thresholds (twice the base).
bool LiesOnANeighbour(const SegmentContext& c, const std::vector<int>& labels,
                      const std::vector<RegionState>& regions, int id) {
  const RegionState& r = regions[id];
  std::vector<int> beside;
  for (const int v : r.vertices) {
    for (const int u : c.graph.Neighbors(v)) {
      const int other = labels[u];
      if (other >= 0 && other != id && regions[other].alive &&
          std::find(beside.begin(), beside.end(), other) == beside.end()) {
        beside.push_back(other);
      }
    }
  }
  const Tolerance tol = Stepped(c, 0);
  std::size_t on = 0;
  for (const int v : r.vertices) {
    on += std::any_of(beside.begin(), beside.end(), [&](int other) {
      return Fits(c, v, ProjectVertex(c, regions[other].surface, v), tol);
    });
  }
  return on >= kOnNeighbourShare * r.vertices.size();
}

// A mesh is exact when its estimated noise is below this fraction of l_avg
// (CAD exports and noise-free generated parts: 0 to 1e-15 l_avg; the
// cleanest scanned mesh measured, 2.5e-4).
constexpr double kExactNoise = 1e-9;

// A plane of kMinInteriorVertices, flat within kFaceSigmas (or exact), that
// lies on no neighbour: a face of its own under the size floor.
bool IsSmallFace(const SegmentContext& c, const std::vector<int>& labels,
                 const std::vector<RegionState>& regions, int id) {
  const RegionState& r = regions[id];
  if (r.type != SurfaceType::kPlane || r.vertices.size() < kMinInteriorVertices) return false;
  const double rms = std::sqrt(SquaredDistances(c, r.surface, r.vertices) / r.vertices.size());
  return rms <= std::max(kFaceSigmas * c.noise_sigma, kExactNoise * c.mean_edge_length) &&
         !LiesOnANeighbour(c, labels, regions, id);
}

}  // namespace

void ReleaseSmallQuadrics(const SegmentContext& c, std::vector<int>* labels,
                          std::vector<RegionState>* regions) {
  const std::size_t min_size =
      std::max(kMinQuadricVertices, static_cast<std::size_t>(kMinQuadricShare * c.vertex_count()));
  ReleaseRegions(
      [&](int, const RegionState& r) {
        return r.type == SurfaceType::kQuadric && r.vertices.size() < min_size;
      },
      labels, regions);
}

int ReleaseSmallRegions(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions) {
  const std::size_t min_size =
      std::max(kMinRegionVertices, static_cast<std::size_t>(kMinRegionShare * c.vertex_count()));
  return ReleaseRegions(
      [&](int id, const RegionState& r) {
        return r.vertices.size() < min_size && !IsSmallFace(c, *labels, *regions, id);
      },
      labels, regions);
}

int ReleaseNarrowPlanes(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions) {
  return ReleaseRegions(
      [&](int id, const RegionState& r) {
        const int ids[] = {id};
        return r.type == SurfaceType::kPlane &&
               InteriorVertices(c, *labels, ids, r.vertices).size() < kMinInteriorVertices &&
               !IsSmallFace(c, *labels, *regions, id);
      },
      labels, regions);
}

absl::Status AbsorbLeftovers(const SegmentContext& c, std::vector<int>* labels,
                             std::vector<RegionState>* regions) {
  for (int step = 0; step < kSteps; ++step) {
    MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
    const Tolerance tol = Stepped(c, step);
    while (Sweep(c, *regions, &tol, labels) > 0) {
    }
  }
  while (Sweep(c, *regions, nullptr, labels) > 0) {
  }
  TypeIslands(c, labels, regions);
  RebuildVertexLists(*labels, regions);
  return absl::OkStatus();
}

}  // namespace meshseg::segment_internal
