#include "segment/energy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "segment/absorb_leftovers.h"
#include "segment/decide_type.h"
#include "segment/facet_on_surface.h"

namespace meshseg::segment_internal {
namespace {

// a_v / a_mean, a_mean the vertex area of a regular triangulation of edge
// l_avg (six equilateral triangles share each vertex: sqrt(3)/2 l_avg^2),
// so no pass over the mesh is needed per call.
double AreaWeight(const SegmentContext& c, int v) {
  const double l = c.mean_edge_length;
  const double mean_area = 0.5 * std::sqrt(3.0) * l * l;
  return mean_area > 0.0 ? c.vertex_area[v] / mean_area : 1.0;
}

// D_v for vertex v at signed distance `distance` from its surface.
double CostAtDistance(const SegmentContext& c, int v, double distance) {
  if (!c.Measured(v)) return 0.0;
  const double d = distance / c.tolerance.distance;
  const double scaled = kToleranceSigmas * kToleranceSigmas * d * d;
  const double mismatch = std::min(std::isfinite(scaled) ? scaled : kOutlierMismatch,
                                   kOutlierMismatch);
  return 0.5 * AreaWeight(c, v) * (mismatch * c.unit_scale);
}

// The data cost of `vertices` on `surface`, summed until it reaches `limit`
// (the terms are not negative: a sum that reached it ends at least there).
double DataCostUpTo(const SegmentContext& c, const Surface& surface,
                    std::span<const int> vertices, double limit) {
  double sum = 0.0;
  const SurfaceDistance distance_to(surface);
  for (const int v : vertices) {
    sum += VertexCost(c, v, distance_to);
    if (sum >= limit) break;
  }
  return sum;
}

}  // namespace

PricedFit PriceFit(const SegmentContext& c, SurfaceType type, std::span<const int> vertices,
                   double stop) {
  PricedFit out;
  const FitResult fit = FitType(c, type, vertices);
  if (!fit.ok()) return out;
  out.surface = fit.surface;
  // Re-estimation on the inliers: rows along creases pull a least-squares
  // fit off the face; the fit to the vertices within th_dis of it does not.
  // (One distance per vertex gives both its cost and whether it is in:
  // SurfaceDistance is ProjectVertex's distance to the bit, without the foot
  // point and normal.)
  std::vector<int> inliers;
  inliers.reserve(vertices.size());
  double cost = 0.0;
  const SurfaceDistance distance_to(fit.surface);
  for (const int v : vertices) {
    const double distance = distance_to(c.position(v), c.normal(v));
    cost += CostAtDistance(c, v, distance);
    if (std::abs(distance) < c.tolerance.distance) inliers.push_back(v);
  }
  out.cost = cost;
  if (inliers.size() == vertices.size() || inliers.size() < kMinRegionVertices) return out;
  const FitResult refit = FitType(c, type, inliers);
  if (!refit.ok()) return out;
  // The refit is kept only if it costs less, and only a cost under `stop`
  // matters: its sum ends where it reaches either.
  const double refit_cost = DataCostUpTo(c, refit.surface, vertices, std::min(out.cost, stop));
  if (refit_cost < out.cost && refit_cost < stop) {
    out.cost = refit_cost;
    out.surface = refit.surface;
  }
  return out;
}

double VertexCost(const SegmentContext& c, int v, const Surface& surface) {
  return CostAtDistance(c, v, SignedDistance(surface, c.position(v), c.normal(v)));
}

double VertexCost(const SegmentContext& c, int v, const SurfaceDistance& distance_to) {
  return CostAtDistance(c, v, distance_to(c.position(v), c.normal(v)));
}

double OutlierCost(const SegmentContext& c, int v) {
  if (!c.Measured(v)) return 0.0;
  return 0.5 * AreaWeight(c, v) * (kOutlierMismatch * c.unit_scale);
}

double DataCost(const SegmentContext& c, const Surface& surface, std::span<const int> vertices) {
  double sum = 0.0;
  const SurfaceDistance distance_to(surface);
  for (const int v : vertices) sum += VertexCost(c, v, distance_to);
  return sum;
}

namespace {

// (p / (2 f)) ln (f n) for `parameters` p.
double LabelCostOf(int parameters, std::size_t vertex_count, double f) {
  const double effective = f * static_cast<double>(vertex_count);
  if (!(effective > 1.0)) return 0.0;
  return 0.5 * parameters * std::log(effective) / f;
}

}  // namespace

double LabelCost(SurfaceType type, std::size_t vertex_count, double f) {
  return LabelCostOf(ParameterCount(type), vertex_count, f);
}

double LabelCost(const SegmentContext& c, SurfaceType type, std::size_t measured_count) {
  return LabelCost(type, measured_count, c.evidence_share);
}

int FreeParameters(const RegionState& r) {
  return ParameterCount(r.type) - r.shared_parameters;
}

double LabelCost(const SegmentContext& c, const RegionState& r, std::size_t measured_count) {
  return LabelCostOf(FreeParameters(r), measured_count, c.evidence_share);
}

double LabelCost(const SegmentContext& c, const RegionState& r) {
  return LabelCost(c, r, MeasuredCount(c, r.vertices));
}

double ExactFacetCost(const FacetMesh& fm, int f, const Surface& surface, double tau) {
  return FacetOnSurface(fm, f, surface, tau) ? 0.0 : std::numeric_limits<double>::infinity();
}

double ExactLabelCost(SurfaceType type, std::size_t corner_count) {
  return LabelCost(type, corner_count, 1.0);
}

double ExactPricePerCorner(SurfaceType type, std::size_t corner_count) {
  if (corner_count == 0) return std::numeric_limits<double>::infinity();
  return ExactLabelCost(type, corner_count) / static_cast<double>(corner_count);
}

double ExactJoinDelta(SurfaceType type, std::size_t a_corners, std::size_t b_corners,
                      double joint_data_cost) {
  const std::size_t counts[] = {a_corners, b_corners};
  return ExactJoinDelta(type, counts, joint_data_cost);
}

double ExactJoinDelta(SurfaceType type, std::span<const std::size_t> corner_counts,
                      double joint_data_cost) {
  std::size_t total = 0;
  double apart = 0.0;
  for (const std::size_t n : corner_counts) {
    total += n;
    apart += ExactLabelCost(type, n);
  }
  return joint_data_cost + ExactLabelCost(type, total) - apart;
}

double EdgeCost(const SegmentContext& c, int u, int v) {
  const bool crease = c.curvature->sharp[u] || c.curvature->sharp[v];
  return kBoundaryCost * (crease ? kCreaseEdgeWeight : 1.0) / c.evidence_share;
}

double BoundaryCost(const SegmentContext& c, const std::vector<int>& labels,
                    std::span<const int> a_vertices, int b) {
  double sum = 0.0;
  for (const int v : a_vertices) {
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] == b) sum += EdgeCost(c, u, v);
    }
  }
  return sum;
}

double TotalEnergy(const SegmentContext& c, const std::vector<int>& labels,
                   const std::vector<RegionState>& regions) {
  // Each vertex's data term on its own (it reads only its label's surface),
  // side by side; then every term added in vertex order as before: the same
  // sum.
  const int n = c.vertex_count();
  std::vector<double> data(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int v = b.begin(); v < b.end(); ++v) {
      const int r = labels[v];
      data[v] = r < 0 ? OutlierCost(c, v) : VertexCost(c, v, regions[r].surface);
    }
  });
  double e = 0.0;
  for (int v = 0; v < n; ++v) {
    const int r = labels[v];
    e += data[v];
    for (const int u : c.graph.Neighbors(v)) {
      if (u > v && labels[u] != r) e += EdgeCost(c, u, v);
    }
  }
  for (const RegionState& r : regions) {
    if (r.alive) e += LabelCost(c, r);
  }
  return e;
}

std::optional<Surface> FitForEnergy(const SegmentContext& c, SurfaceType type,
                                    std::span<const int> vertices) {
  return PriceFit(c, type, vertices).surface;
}

namespace {

// Region `r` re-estimated, with the data cost of its vertices on the surface
// it keeps.
std::pair<RegionState, double> ReestimatedWithCost(const SegmentContext& c, const RegionState& r) {
  RegionState out = r;
  const PricedFit fit = PriceFit(c, r.type, r.vertices);
  const double cost = DataCost(c, r.surface, r.vertices);
  // The label cost the free refit adds (0 for a surface fitted free).
  const std::size_t measured = MeasuredCount(c, r.vertices);
  const double freed = LabelCost(c, r.type, measured) - LabelCost(c, r, measured);
  if (fit.surface && fit.cost + freed < cost) {
    out.surface = *fit.surface;
    out.shared_parameters = 0;
    return {std::move(out), fit.cost};
  }
  return {std::move(out), cost};
}

}  // namespace

RegionState Reestimated(const SegmentContext& c, const RegionState& r) {
  return ReestimatedWithCost(c, r).first;
}

const ReestimatedRegions::Priced& ReestimatedRegions::Get(int id) {
  const RegionState& r = regions_[id];
  auto it = cache_.find({id, r.vertices.size()});
  if (it == cache_.end()) {
    Priced priced;
    if (reestimate_) {
      auto [region, cost] = ReestimatedWithCost(c_, r);
      priced = {.region = std::move(region), .cost = cost};
    } else {
      priced = {.region = r, .cost = DataCost(c_, r.surface, r.vertices)};
    }
    it = cache_.emplace(std::pair{id, r.vertices.size()}, std::move(priced)).first;
  }
  return it->second;
}

std::vector<SurfaceType> MergeTypes(SurfaceType a, SurfaceType b) {
  constexpr SurfaceType kAnalytic[] = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                       SurfaceType::kSphere, SurfaceType::kCone,
                                       SurfaceType::kTorus};
  const bool quadric = a == SurfaceType::kQuadric || b == SurfaceType::kQuadric;
  std::vector<SurfaceType> types;
  for (const SurfaceType t : kAnalytic) {
    if (quadric || t == a || t == b || !(IsLimitOf(a, t) || IsLimitOf(b, t))) types.push_back(t);
  }
  if (quadric) types.push_back(SurfaceType::kQuadric);
  return types;
}

std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               const std::vector<RegionState>& regions, int a, int b,
                               std::span<const SurfaceType> types) {
  return MergeDelta(c, labels, regions[a], a, regions[b], b, types);
}

namespace {

// MergeDelta of `x` and `y` with data costs `x_cost` and `y_cost` on their
// surfaces; a type whose move cannot lower E below `below` (nor below the
// best type before it) is priced no further than that shows.
std::optional<Move> PriceMerge(const SegmentContext& c, const std::vector<int>& labels,
                               const RegionState& x, int a, double x_cost, const RegionState& y,
                               int b, double y_cost, std::span<const SurfaceType> types,
                               double below) {
  // The union, sorted: a merge of the two sorted lists (a region's list is
  // kept sorted), which is what sorting them together gives.
  std::vector<int> both(x.vertices.size() + y.vertices.size());
  if (std::is_sorted(x.vertices.begin(), x.vertices.end()) &&
      std::is_sorted(y.vertices.begin(), y.vertices.end())) {
    std::merge(x.vertices.begin(), x.vertices.end(), y.vertices.begin(), y.vertices.end(),
               both.begin());
  } else {
    std::copy(y.vertices.begin(), y.vertices.end(),
              std::copy(x.vertices.begin(), x.vertices.end(), both.begin()));
    std::sort(both.begin(), both.end());
  }
  const bool x_smaller = x.vertices.size() <= y.vertices.size();
  const double before = x_cost + y_cost +
                        BoundaryCost(c, labels, x_smaller ? x.vertices : y.vertices,
                                     x_smaller ? b : a) +
                        LabelCost(c, x) + LabelCost(c, y);
  std::optional<Move> best;
  const std::size_t measured = MeasuredCount(c, both);
  for (const SurfaceType type : types) {
    const double label = LabelCost(c, type, measured);
    // A cost at or above this makes the move no better than `below` or the
    // best so far (with a margin far above the rounding of the sums).
    const double worth = best ? std::min(below, best->delta) : below;
    const double stop = before - label + worth + 1e-9 * (std::abs(before) + label + 1.0);
    const PricedFit fit = PriceFit(c, type, both, stop);
    if (!fit.surface) continue;
    const double delta = fit.cost + label - before;
    if (!best || delta < best->delta) {
      best = Move{.delta = delta, .type = type, .surface = *fit.surface};
    }
  }
  return best;
}

}  // namespace

std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               const RegionState& x, int a, const RegionState& y, int b,
                               std::span<const SurfaceType> types) {
  return PriceMerge(c, labels, x, a, DataCost(c, x.surface, x.vertices), y, b,
                    DataCost(c, y.surface, y.vertices), types,
                    std::numeric_limits<double>::infinity());
}

std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               ReestimatedRegions& region, int a, int b,
                               std::span<const SurfaceType> types, double below) {
  return PriceMerge(c, labels, region(a), a, region.Cost(a), region(b), b, region.Cost(b), types,
                    below);
}

std::optional<Move> RetypeDelta(const SegmentContext& c, const RegionState& r, SurfaceType type) {
  const PricedFit fit = PriceFit(c, type, r.vertices);
  if (!fit.surface) return std::nullopt;
  const double before = DataCost(c, r.surface, r.vertices) + LabelCost(c, r);
  return Move{.delta = fit.cost + LabelCost(c, type, MeasuredCount(c, r.vertices)) - before,
              .type = type,
              .surface = *fit.surface};
}

}  // namespace meshseg::segment_internal
