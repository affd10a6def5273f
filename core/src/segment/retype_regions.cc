#include "segment/retype_regions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include <tbb/parallel_for.h>

#include "segment/decide_type.h"
#include "segment/energy.h"

namespace meshseg::segment_internal {
namespace {

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

// RetypeInaccurateCurved proposes a type for curved regions whose model
// error exceeds this many noise sigmas (rms above 1.12 sigma).
constexpr double kInaccurateError = 0.5;

}  // namespace

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

bool RetypeIfLower(const SegmentContext& c, RegionState* r, std::span<const SurfaceType> types) {
  std::optional<RegionState> own;  // re-estimated once, if any type is new
  std::optional<Move> best;
  for (const SurfaceType type : types) {
    if (type == r->type) continue;
    if (!own) own = Reestimated(c, *r);
    const std::optional<Move> move = RetypeDelta(c, *own, type);
    if (move && (!best || move->delta < best->delta)) best = move;
  }
  if (!best || !(best->delta < 0.0)) return false;
  r->type = best->type;
  r->surface = best->surface;
  return true;
}

bool RetypeCurved(const SegmentContext& c, RegionState* r) {
  const std::vector<int> smooth = SmoothVertices(c, r->vertices);
  if (smooth.size() < kMinRetypeVertices) return false;
  const TypedFit curved = DecideCurvedType(c, smooth, c.tolerance);
  if (curved.type == SurfaceType::kQuadric) return false;
  const SurfaceType types[] = {curved.type};
  return RetypeIfLower(c, r, types);
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
    // The proposals: the plane and the curved type of S1's order.
    const SurfaceType curved = DecideCurvedType(c, smooth, c.tolerance).type;
    std::vector<SurfaceType> types = {SurfaceType::kPlane};
    if (curved != SurfaceType::kQuadric) types.push_back(curved);
    if (RetypeIfLower(c, &r, types)) retyped.push_back(id);
  }
  return retyped;
}

int RetypeToSimplerLimits(const SegmentContext& c, std::vector<RegionState>* regions) {
  std::vector<uint8_t> retyped(regions->size(), 0);
  // Each proposal reads and changes its own region only: concurrent.
  tbb::parallel_for(std::size_t{0}, regions->size(), [&](std::size_t id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type) || r.vertices.size() < kMinRetypeVertices) return;
    std::vector<SurfaceType> types = {SurfaceType::kPlane};
    if (r.type == SurfaceType::kCone) types.push_back(SurfaceType::kCylinder);
    retyped[id] = RetypeIfLower(c, &r, types);
  });
  return static_cast<int>(std::count(retyped.begin(), retyped.end(), 1));
}

}  // namespace meshseg::segment_internal
