// EvidenceShare and NormalShare (energy.h): the share of independent samples
// in the residuals of a segmentation, in position and in normal, from their
// lag-1 autocorrelation over mesh edges.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <vector>

#include "segment/energy.h"

namespace meshseg::segment_internal {
namespace {

// A residual of a vertex on its region's surface: a scalar (the distance)
// or a vector (the tangential part of the normal), nullopt where the data
// term does not use it.
using Residual = std::function<std::optional<Eigen::Vector3d>(int v)>;

// (1 - rho) / (1 + rho), rho = sum r_u . r_v / sum ((|r_u|^2 + |r_v|^2) / 2
// + delta^2) over the edges inside a region with both ends non-sharp and a
// residual, from a fixed-stride sample; 1 if rho <= 0 or nothing to
// measure.
double ShareOf(const SegmentContext& c, const std::vector<int>& labels,
               const std::vector<RegionState>& regions, const Residual& residual,
               double delta) {
  std::vector<int> labelled;
  for (int v = 0; v < c.vertex_count(); ++v) {
    if (labels[v] >= 0 && !c.curvature->sharp[v]) labelled.push_back(v);
  }
  double products = 0.0, squares = 0.0;
  long pairs = 0;
  for (const int v : Sample(labelled)) {
    if (!regions[labels[v]].alive) continue;
    const std::optional<Eigen::Vector3d> rv = residual(v);
    if (!rv) continue;
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] != labels[v] || c.curvature->sharp[u]) continue;
      const std::optional<Eigen::Vector3d> ru = residual(u);
      if (!ru) continue;
      products += rv->dot(*ru);
      squares += 0.5 * (rv->squaredNorm() + ru->squaredNorm());
      ++pairs;
    }
  }
  // Every residual is known to the data term only to its resolution delta
  // (energy.h): an independent term of variance delta^2 in each.
  const double variance = squares + static_cast<double>(pairs) * delta * delta;
  if (!(variance > 0.0)) return 1.0;
  const double rho = std::clamp(products / variance, 0.0, 1.0);
  return (1.0 - rho) / (1.0 + rho);
}

}  // namespace

double EvidenceShare(const SegmentContext& c, const std::vector<int>& labels,
                     const std::vector<RegionState>& regions) {
  const Residual distance = [&](int v) -> std::optional<Eigen::Vector3d> {
    const double d = ProjectVertex(c, regions[labels[v]].surface, v).distance;
    if (!(std::abs(d) < c.tolerance.distance)) return std::nullopt;
    return Eigen::Vector3d(d, 0.0, 0.0);
  };
  return ShareOf(c, labels, regions, distance,
                 kResidualResolution * c.tolerance.distance / kToleranceSigmas);
}

double NormalShare(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions) {
  // Radians of tilt per degree; the tilt whose normal term alone reaches
  // c_out (k th_nm / k_n) bounds the residuals used, as th_dis does the
  // distances.
  const double radians = std::numbers::pi / 180.0;
  const double unit = c.angle_tolerance_deg * radians / kNormalSigmas;
  const double limit = std::sin(std::min(kToleranceSigmas * unit, 0.5 * std::numbers::pi));
  const Residual tangential = [&](int v) -> std::optional<Eigen::Vector3d> {
    const Projection pr = ProjectVertex(c, regions[labels[v]].surface, v);
    if (!(std::abs(pr.distance) < c.tolerance.distance)) return std::nullopt;
    const Eigen::Vector3d& n = c.curvature->normal[v];
    const Eigen::Vector3d t = n - n.dot(pr.normal) * pr.normal;
    if (!(t.norm() < limit)) return std::nullopt;
    return t;
  };
  return ShareOf(c, labels, regions, tangential, kResidualResolution * unit);
}

}  // namespace meshseg::segment_internal
