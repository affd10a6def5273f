#include "segment/energy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "segment/absorb_leftovers.h"
#include "segment/decide_type.h"

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

// The data cost of `vertices` under a surface of `type` fitted to them for
// least energy, with the surface (infinite cost if none is valid).
struct PricedFit {
  double cost = std::numeric_limits<double>::infinity();
  std::optional<Surface> surface;
};

PricedFit PriceFit(const SegmentContext& c, SurfaceType type, std::span<const int> vertices) {
  PricedFit out;
  const FitResult fit = FitType(c, type, vertices);
  if (!fit.ok()) return out;
  out.cost = DataCost(c, fit.surface, vertices);
  out.surface = fit.surface;
  // Re-estimation on the inliers: rows along creases pull a least-squares
  // fit off the face; the fit to the vertices within th_dis of it does not.
  std::vector<int> inliers;
  inliers.reserve(vertices.size());
  for (const int v : vertices) {
    if (std::abs(ProjectVertex(c, fit.surface, v).distance) < c.tolerance.distance) {
      inliers.push_back(v);
    }
  }
  if (inliers.size() == vertices.size() || inliers.size() < kMinRegionVertices) return out;
  const FitResult refit = FitType(c, type, inliers);
  if (!refit.ok()) return out;
  const double cost = DataCost(c, refit.surface, vertices);
  if (cost < out.cost) {
    out.cost = cost;
    out.surface = refit.surface;
  }
  return out;
}

}  // namespace

double VertexCost(const SegmentContext& c, int v, const Surface& surface) {
  const double d = ProjectVertex(c, surface, v).distance / c.tolerance.distance;
  const double scaled = kToleranceSigmas * kToleranceSigmas * d * d;
  return 0.5 * AreaWeight(c, v) * std::min(std::isfinite(scaled) ? scaled : kOutlierMismatch,
                                           kOutlierMismatch);
}

double OutlierCost(const SegmentContext& c, int v) {
  return 0.5 * AreaWeight(c, v) * kOutlierMismatch;
}

double DataCost(const SegmentContext& c, const Surface& surface, std::span<const int> vertices) {
  double sum = 0.0;
  for (const int v : vertices) sum += VertexCost(c, v, surface);
  return sum;
}

double LabelCost(SurfaceType type, std::size_t vertex_count) {
  if (vertex_count <= 1) return 0.0;
  return 0.5 * ParameterCount(type) * std::log(static_cast<double>(vertex_count));
}

double EdgeCost(const SegmentContext& c, int u, int v) {
  const bool crease = c.curvature->sharp[u] || c.curvature->sharp[v];
  return kBoundaryCost * (crease ? kCreaseEdgeWeight : 1.0);
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
  double e = 0.0;
  for (int v = 0; v < c.vertex_count(); ++v) {
    const int r = labels[v];
    e += r < 0 ? OutlierCost(c, v) : VertexCost(c, v, regions[r].surface);
    for (const int u : c.graph.Neighbors(v)) {
      if (u > v && labels[u] != r) e += EdgeCost(c, u, v);
    }
  }
  for (const RegionState& r : regions) {
    if (r.alive) e += LabelCost(r.type, r.vertices.size());
  }
  return e;
}

std::optional<Surface> FitForEnergy(const SegmentContext& c, SurfaceType type,
                                    std::span<const int> vertices) {
  return PriceFit(c, type, vertices).surface;
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

std::optional<Move> MergeDelta(const SegmentContext& c, const std::vector<int>& labels,
                               const RegionState& x, int a, const RegionState& y, int b,
                               std::span<const SurfaceType> types) {
  std::vector<int> both = x.vertices;
  both.insert(both.end(), y.vertices.begin(), y.vertices.end());
  std::sort(both.begin(), both.end());
  const bool x_smaller = x.vertices.size() <= y.vertices.size();
  const double before = DataCost(c, x.surface, x.vertices) + DataCost(c, y.surface, y.vertices) +
                        BoundaryCost(c, labels, x_smaller ? x.vertices : y.vertices,
                                     x_smaller ? b : a) +
                        LabelCost(x.type, x.vertices.size()) + LabelCost(y.type, y.vertices.size());
  std::optional<Move> best;
  for (const SurfaceType type : types) {
    const PricedFit fit = PriceFit(c, type, both);
    if (!fit.surface) continue;
    const double delta = fit.cost + LabelCost(type, both.size()) - before;
    if (!best || delta < best->delta) {
      best = Move{.delta = delta, .type = type, .surface = *fit.surface};
    }
  }
  return best;
}

std::optional<Move> RetypeDelta(const SegmentContext& c, const RegionState& r, SurfaceType type) {
  const PricedFit fit = PriceFit(c, type, r.vertices);
  if (!fit.surface) return std::nullopt;
  const double before = DataCost(c, r.surface, r.vertices) + LabelCost(r.type, r.vertices.size());
  return Move{.delta = fit.cost + LabelCost(type, r.vertices.size()) - before,
              .type = type,
              .surface = *fit.surface};
}

double DropDelta(const SegmentContext& c, const std::vector<int>& labels,
                 const std::vector<RegionState>& regions, int id, std::vector<int>* takers) {
  const RegionState& r = regions[id];
  const std::vector<int> around = RegionsAround(c, labels, regions, id);
  // The new label of each of r's vertices, in the order of r.vertices.
  std::vector<int> next(r.vertices.size(), -1);
  double delta = -LabelCost(r.type, r.vertices.size());
  for (std::size_t k = 0; k < r.vertices.size(); ++k) {
    const int v = r.vertices[k];
    double best = OutlierCost(c, v);
    for (const int o : around) {
      const double cost = VertexCost(c, v, regions[o].surface);
      if (cost < best) best = cost, next[k] = o;
    }
    delta += best - VertexCost(c, v, r.surface);
  }
  if (takers != nullptr) {
    *takers = next;
    std::sort(takers->begin(), takers->end());
    takers->erase(std::unique(takers->begin(), takers->end()), takers->end());
  }
  // The neighbours grow: their label costs by the vertices they take.
  std::vector<std::size_t> gained(regions.size(), 0);
  for (const int o : next) {
    if (o >= 0) ++gained[o];
  }
  for (const int o : around) {
    const std::size_t n = regions[o].vertices.size();
    delta += LabelCost(regions[o].type, n + gained[o]) - LabelCost(regions[o].type, n);
  }
  // The edges at r's vertices, before and after (each edge inside r once).
  std::unordered_map<int, int> after;
  for (std::size_t k = 0; k < r.vertices.size(); ++k) after[r.vertices[k]] = next[k];
  auto label_after = [&](int u) { return labels[u] == id ? after.at(u) : labels[u]; };
  for (const int v : r.vertices) {
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] == id && u < v) continue;
      const double w = EdgeCost(c, u, v);
      delta += ((label_after(u) != label_after(v)) - (labels[u] != labels[v])) * w;
    }
  }
  return delta;
}

}  // namespace meshseg::segment_internal
