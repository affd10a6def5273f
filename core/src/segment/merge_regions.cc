#include "segment/merge_regions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "meshseg/status_macros.h"
#include "segment/absorb_leftovers.h"
#include "segment/decide_type.h"
#include "segment/region_graph.h"

namespace meshseg::segment_internal {
namespace {

void Refit(const SegmentContext& c, RegionState* r) {
  FitResult fit = FitType(c, r->type, r->vertices);
  if (fit.ok()) r->surface = fit.surface;
}

// The non-sharp vertices of `vertices` (all of them if fewer than
// kMinRetypeVertices are smooth): absorbed vertices next to sharp edges
// carry bent normals and say little about the surface.
std::vector<int> SmoothVertices(const SegmentContext& c, const std::vector<int>& vertices) {
  std::vector<int> smooth;
  for (const int v : vertices) {
    if (!c.curvature->sharp[v]) smooth.push_back(v);
  }
  return smooth.size() < kMinRetypeVertices ? vertices : smooth;
}

// Alive regions, largest first (ties by id).
std::vector<int> BySize(const std::vector<RegionState>& regions) {
  std::vector<int> order;
  for (int id = 0; id < static_cast<int>(regions.size()); ++id) {
    if (regions[id].alive && !regions[id].vertices.empty()) order.push_back(id);
  }
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
    return regions[x].vertices.size() > regions[y].vertices.size();
  });
  return order;
}

// ALGORITHMS.md S1 step 3.3; returns the number of merges. All smooth arcs are
// tried, whatever the types: a sphere of large radius seen as a small plane
// fits the sphere's surface and is merged (the beta1 test is strict).
int MergeByExtrapolation(const SegmentContext& c, std::vector<int>* labels,
                         std::vector<RegionState>* regions) {
  const std::vector<RegionArc> arcs = BuildRegionGraph(c, *labels, *regions);
  std::map<int, std::vector<int>> neighbours;
  for (const RegionArc& arc : arcs) {
    if (!arc.smooth) continue;
    neighbours[arc.a].push_back(arc.b);
    neighbours[arc.b].push_back(arc.a);
  }
  int merges = 0;
  for (const int i : BySize(*regions)) {
    RegionState& ri = (*regions)[i];
    if (!ri.alive) continue;
    bool grew = false;
    for (const int j : neighbours[i]) {
      const RegionState& rj = (*regions)[j];
      if (!rj.alive || rj.vertices.size() > ri.vertices.size()) continue;
      if (FitFraction(c, ri.surface, SmoothVertices(c, rj.vertices), c.tolerance) <= kBeta1) {
        continue;
      }
      MergeInto(i, j, labels, regions);
      grew = true;
      ++merges;
    }
    if (grew) Refit(c, &ri);
  }
  return merges;
}

// The order of types of ALGORITHMS.md S1 step 2.5, with S2's torus: plane,
// cylinder, sphere, cone, torus, quadric.
int TypeRank(SurfaceType t) {
  switch (t) {
    case SurfaceType::kPlane: return 0;
    case SurfaceType::kCylinder: return 1;
    case SurfaceType::kSphere: return 2;
    case SurfaceType::kCone: return 3;
    case SurfaceType::kTorus: return 4;
    case SurfaceType::kQuadric:
    case SurfaceType::kFreeform: return 5;
  }
  return 5;
}

// Fractions within this of each other count as equal (simpler type wins).
constexpr double kFractionTie = 0.02;
// RetypeInaccurateCurved looks again at curved regions whose model error
// exceeds this many noise sigmas (rms above 1.12 sigma).
constexpr double kInaccurateError = 0.5;
// ... and takes a type that fits this share of a region its own type no
// longer fits validly (the trim share of the initial segmentation).
constexpr double kStaleTypeFraction = 0.75;
// A union fitting a region as well as its own surface must still fit this
// share of it (MergeByRefitting).
constexpr double kMinUnionFraction = 0.5;

struct PairFit {
  double fraction_x = 0.0, fraction_y = 0.0;  // of each region's vertices meeting (5), (6)
  double fraction() const { return std::min(fraction_x, fraction_y); }
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
};

// The union of the two regions fitted with their type, scored by the
// smaller of the two regions' fitting fractions (a large region alone would
// otherwise carry any small neighbour past beta2). An analytic region only
// merges with a quadric if its own type fits the union: a quadric bends
// enough to cover a plane and its tangent fillet at once.
PairFit FitUnion(const SegmentContext& c, const RegionState& x, const RegionState& y) {
  std::vector<int> both = x.vertices;
  both.insert(both.end(), y.vertices.begin(), y.vertices.end());
  std::sort(both.begin(), both.end());
  // Both members' types are tried (the order of the arc must not matter: a
  // large-radius cylinder fitted to a plane and a sliver would turn the
  // plane into a cylinder); the simpler one wins near-ties.
  std::vector<SurfaceType> types;
  for (const SurfaceType t : {x.type, y.type}) {
    if (t != SurfaceType::kQuadric) types.push_back(t);
  }
  if (types.empty()) types.push_back(SurfaceType::kQuadric);
  // Two planes across a smooth arc may be facets of one cylinder: at high
  // noise th_dis and th_nm let a radius-10 h fillet pass as planes 20-25°
  // wide, which no plane fits as a pair.
  if (x.type == SurfaceType::kPlane && y.type == SurfaceType::kPlane) {
    types.push_back(SurfaceType::kCylinder);
  }
  std::sort(types.begin(), types.end(),
            [](SurfaceType a, SurfaceType b) { return TypeRank(a) < TypeRank(b); });
  types.erase(std::unique(types.begin(), types.end()), types.end());
  PairFit best;
  for (const SurfaceType type : types) {
    const FitResult fit = FitType(c, type, both);
    if (!fit.ok()) continue;
    const double fx = FitFraction(c, fit.surface, x.vertices, c.tolerance);
    const double fy = FitFraction(c, fit.surface, y.vertices, c.tolerance);
    if (std::min(fx, fy) > best.fraction() + kFractionTie) {
      best = PairFit{.fraction_x = fx, .fraction_y = fy, .type = type, .surface = fit.surface};
    }
  }
  return best;
}

// Whether the union's surface, of r's own type, fits region `r` (fraction
// `f`) within kFractionTie as well as r's own surface does, and at least
// kMinUnionFraction of it; r must have kMinRegionVertices (on fewer the
// fractions are too coarse to compare: one vertex of 47 is 2 %).
bool FitsAsWellAsOwn(const SegmentContext& c, const RegionState& r, const PairFit& fit, double f) {
  return fit.type == r.type && r.vertices.size() >= kMinRegionVertices &&
         f >= kMinUnionFraction &&
         f + kFractionTie >= FitFraction(c, r.surface, r.vertices, c.tolerance);
}

// ALGORITHMS.md S1 step 3.4: repeatedly merges the best-fitting pair: one
// whose union one surface fits to beta2 on both regions, or, for two regions
// of one type, as well as each region's own surface fits it. The second
// clause is ours: at sigma = 0.15 h the rows along creases and the noise in
// n'_i leave a region's own surface meeting (5) and (6) on 75-87 % of its
// vertices (a half-cylinder groove of r 7 across a plane face, grown from
// two seeds: 80 to 87 % over two noise draws), so no union could pass beta2
// and the groove stayed two cylinders whose boundary the refinement then
// drew through the noise. One type and kMinRegionVertices: without them two
// cone fragments of 47 and 24 vertices, and two plane strips read as one
// cylinder, merged, and each left a 45-degree countersink band in two
// pieces typed apart.
absl::Status MergeByRefitting(const SegmentContext& c, std::vector<int>* labels,
                              std::vector<RegionState>* regions) {
  return MergeBestPairs(
             c, labels, regions, [](const RegionArc& arc) { return arc.kept; },
             [&](int a, int b) -> std::optional<PairMerge> {
               const RegionState& x = (*regions)[a];
               const RegionState& y = (*regions)[b];
               const PairFit fit = FitUnion(c, x, y);
               if (fit.fraction() < kBeta2 && !(FitsAsWellAsOwn(c, x, fit, fit.fraction_x) &&
                                              FitsAsWellAsOwn(c, y, fit, fit.fraction_y))) {
                 return std::nullopt;
               }
               return PairMerge{.score = fit.fraction(), .type = fit.type, .surface = fit.surface};
             })
      .status();
}

}  // namespace

absl::Status MergeRegions(const SegmentContext& c, std::vector<int>* labels,
                          std::vector<RegionState>* regions) {
  while (MergeByExtrapolation(c, labels, regions) > 0) {
    MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
  }
  MESHSEG_RETURN_IF_ERROR(MergeByRefitting(c, labels, regions));
  RetypeQuadrics(c, regions);
  while (MergeByExtrapolation(c, labels, regions) > 0) {
    MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
  }
  return absl::OkStatus();
}

void RetypeQuadrics(const SegmentContext& c, std::vector<RegionState>* regions) {
  for (RegionState& r : *regions) {
    if (!r.alive || r.type != SurfaceType::kQuadric || r.vertices.empty()) continue;
    // Absorbed vertices next to sharp edges carry bent normals; judge the
    // type on the non-sharp ones.
    std::vector<int> smooth;
    for (const int v : r.vertices) {
      if (!c.curvature->sharp[v]) smooth.push_back(v);
    }
    if (smooth.size() < kMinRetypeVertices) continue;
    std::optional<TypedFit> typed = PlaneIfFits(c, smooth, c.tolerance);
    if (!typed) {
      TypedFit curved = DecideCurvedType(c, smooth, c.tolerance);
      if (curved.fraction > c.alpha) typed = curved;
    }
    if (!typed) continue;
    r.type = typed->type;
    r.surface = typed->fit.surface;
  }
}

bool RetypeCurved(const SegmentContext& c, RegionState* r) {
  const std::vector<int> smooth = SmoothVertices(c, r->vertices);
  if (smooth.size() < kMinRetypeVertices) return false;
  const TypedFit curved = DecideCurvedType(c, smooth, c.tolerance);
  if (!(curved.fraction > c.alpha) || curved.type == SurfaceType::kQuadric) return false;
  r->type = curved.type;
  r->surface = curved.fit.surface;
  return true;
}

std::vector<int> RetypeBentPlanes(const SegmentContext& c, std::vector<RegionState>* regions) {
  std::vector<int> retyped;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || r.type != SurfaceType::kPlane) continue;
    const std::vector<int> smooth = SmoothVertices(c, r.vertices);
    if (smooth.size() < kMinRetypeVertices) continue;
    if (FitFraction(c, r.surface, smooth, c.tolerance) > c.alpha) continue;
    if (RetypeCurved(c, &r)) retyped.push_back(id);
  }
  return retyped;
}

std::vector<int> RetypeInaccurateCurved(const SegmentContext& c,
                                        std::vector<RegionState>* regions) {
  std::vector<int> retyped;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type)) continue;
    const std::vector<int> smooth = SmoothVertices(c, r.vertices);
    if (smooth.size() < kMinRetypeVertices) continue;
    // A type with no valid fit left (a torus whose cusp the region grew
    // over) misses by any amount.
    const FitResult current = FitType(c, r.type, smooth);
    const double error = current.ok() ? ModelError(c, current) : HUGE_VAL;
    if (!(error > kInaccurateError * c.noise_sigma)) continue;
    const TypedFit plane = TryType(c, SurfaceType::kPlane, smooth, c.tolerance);
    TypedFit typed = plane.fraction > c.alpha ? plane : DecideCurvedType(c, smooth, c.tolerance);
    // With no valid fit left, a type that fits kStaleTypeFraction will do:
    // the boundary refinement that follows hands the rest to the
    // neighbours (a plane annulus retyped from a torus holds the first rows
    // of its convex edge round).
    double needed = c.alpha;
    if (!current.ok() && !(typed.fraction > c.alpha)) {
      needed = kStaleTypeFraction;
      if (plane.fraction >= typed.fraction - kFractionTie) typed = plane;
    }
    if (typed.type == r.type || typed.type == SurfaceType::kQuadric ||
        !(typed.fraction >= needed) || !(ModelError(c, typed.fit) < 0.5 * error)) {
      continue;
    }
    r.type = typed.type;
    r.surface = typed.fit.surface;
    retyped.push_back(id);
  }
  return retyped;
}

}  // namespace meshseg::segment_internal
