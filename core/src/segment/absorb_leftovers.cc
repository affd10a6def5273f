#include "segment/absorb_leftovers.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/decide_type.h"

namespace meshseg::segment_internal {
namespace {

// ALGORITHMS.md S2 STB3 steps (1.0, 16°), (1.5, 24°), (2.0, 32°), ... from the base
// (0.5, 8°): multiples 2, 3, 4, ... of the base thresholds.
constexpr int kSteps = 5;
constexpr double kMaxAngleDeg = 80.0;
constexpr double kPi = 3.14159265358979323846;
constexpr int kNoPick = -1;
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
