// EvidenceShare (energy.h): the share of independent samples in the
// residuals of a segmentation, from their lag-1 autocorrelation over mesh
// edges.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "segment/energy.h"

namespace meshseg::segment_internal {

double EvidenceShare(const SegmentContext& c, const std::vector<int>& labels,
                     const std::vector<RegionState>& regions) {
  std::vector<int> labelled;
  for (int v = 0; v < c.vertex_count(); ++v) {
    if (labels[v] >= 0 && !c.curvature->sharp[v] && c.Measured(v)) labelled.push_back(v);
  }
  // The residual of v on its region's surface; nullopt off the surface.
  auto residual = [&](int v) -> std::optional<double> {
    const RegionState& r = regions[labels[v]];
    if (!r.alive) return std::nullopt;
    const double d = ProjectVertex(c, r.surface, v).distance;
    if (!(std::abs(d) < c.tolerance.distance)) return std::nullopt;
    return d;
  };
  double products = 0.0, squares = 0.0;
  long pairs = 0;
  for (const int v : Sample(labelled)) {
    const std::optional<double> dv = residual(v);
    if (!dv) continue;
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] != labels[v] || c.curvature->sharp[u] || !c.Measured(u)) continue;
      const std::optional<double> du = residual(u);
      if (!du) continue;
      products += *dv * *du;
      squares += 0.5 * (*dv * *dv + *du * *du);
      ++pairs;
    }
  }
  // Every residual is known to the data term only to its resolution delta
  // (energy.h): an independent term of variance delta^2 in each.
  const double delta =
      kResidualResolution * c.tolerance.distance / kToleranceSigmas / std::sqrt(c.unit_scale);
  const double variance = squares + static_cast<double>(pairs) * delta * delta;
  if (!(variance > 0.0)) return 1.0;
  const double rho = std::clamp(products / variance, 0.0, 1.0);
  return (1.0 - rho) / (1.0 + rho);
}

}  // namespace meshseg::segment_internal
