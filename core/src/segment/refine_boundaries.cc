#include "segment/refine_boundaries.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One sweep from `labels` into `next` (vertices that stay keep their label).
void Sweep(const SegmentContext& c, const std::vector<RegionState>& regions,
           const std::vector<int>& labels, std::vector<int>* next) {
  tbb::parallel_for(tbb::blocked_range<int>(0, c.vertex_count()), [&](const auto& range) {
    for (int v = range.begin(); v != range.end(); ++v) {
      (*next)[v] = labels[v];
      const int own = labels[v];
      if (own < 0 || c.curvature->sharp[v]) continue;
      double best_score = -1.0;
      int best = own;
      for (const int u : c.graph.Neighbors(v)) {
        const int r = labels[u];
        if (r < 0 || r == own || r == best || !regions[r].alive) continue;
        const Projection pr = ProjectVertex(c, regions[r].surface, v);
        if (!Fits(c, v, pr, c.tolerance)) continue;
        const double score = MismatchScore(c, v, pr);
        if (best == own || score < best_score || (score == best_score && r < best)) {
          best = r;
          best_score = score;
        }
      }
      if (best == own) continue;
      if (best_score < MismatchScore(c, v, ProjectVertex(c, regions[own].surface, v))) {
        (*next)[v] = best;
      }
    }
  });
}

}  // namespace

double MismatchScore(const SegmentContext& c, int v, const Projection& pr) {
  const double cosine = std::min(1.0, std::abs(pr.normal.dot(c.normal(v))));
  const double angle = std::acos(cosine) * 180.0 / kPi / c.angle_tolerance_deg;
  const double distance = pr.distance / c.tolerance.distance;
  if (!std::isfinite(distance) || !std::isfinite(angle)) return HUGE_VAL;
  return distance * distance + angle * angle;
}

absl::Status RefineBoundaries(const SegmentContext& c, std::vector<int>* labels,
                              std::vector<RegionState>* regions) {
  std::vector<int> next(labels->size());
  for (int round = 0; round < kBoundaryRounds; ++round) {
    std::vector<uint8_t> changed(regions->size(), 0);
    for (int sweep = 0; sweep < kMaxBoundarySweeps; ++sweep) {
      MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
      Sweep(c, *regions, *labels, &next);
      int moved = 0;
      for (std::size_t v = 0; v < next.size(); ++v) {
        if (next[v] == (*labels)[v]) continue;
        changed[(*labels)[v]] = 1;
        changed[next[v]] = 1;
        ++moved;
      }
      if (moved == 0) break;
      labels->swap(next);
    }
    RebuildVertexLists(*labels, regions);
    RefitRegions(c, changed, regions);
  }
  return absl::OkStatus();
}

}  // namespace meshseg::segment_internal
