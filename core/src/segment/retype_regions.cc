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

// RetypeIfLower, with `own()` giving region `r` re-estimated.
template <typename Own>
bool RetypeIfLowerThan(const SegmentContext& c, RegionState* r,
                       std::span<const SurfaceType> types, Own own_of) {
  std::optional<RegionState> own;  // re-estimated once, if any type is new
  std::optional<Move> best;
  for (const SurfaceType type : types) {
    if (type == r->type) continue;
    if (!own) own = own_of();
    const std::optional<Move> move = RetypeDelta(c, *own, type);
    if (move && (!best || move->delta < best->delta)) best = move;
  }
  if (!best || !(best->delta < 0.0)) return false;
  r->type = best->type;
  r->surface = best->surface;
  return true;
}

// RetypeIfLower of region `id`, its re-estimation the one `kept` keeps of
// it as it stands (the same as Reestimated's) where there is one.
bool RetypeIfLowerKept(const SegmentContext& c, std::vector<RegionState>* regions, int id,
                       std::span<const SurfaceType> types, KeptPrices* kept) {
  RegionState* r = &(*regions)[id];
  if (kept == nullptr) return RetypeIfLower(c, r, types);
  return RetypeIfLowerThan(c, r, types, [&] { return kept->Reestimation(c, *regions, id); });
}

// Whether proposal `p` is to be asked of region `id`: not if `kept` keeps
// that it made no move on the region as it stands.
bool Ask(const std::vector<RegionState>& regions, int id, KeptPrices* kept,
         KeptPrices::Proposal p) {
  return kept == nullptr || !kept->Refused(regions, id, p);
}

// Keeps, in `kept`, that proposal `p` made no move on region `id`.
void Refused(const std::vector<RegionState>& regions, int id, KeptPrices* kept,
             KeptPrices::Proposal p) {
  if (kept != nullptr) kept->Refuse(regions, id, p);
}

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
  return RetypeIfLowerThan(c, r, types, [&] { return Reestimated(c, *r); });
}

bool RetypeCurved(const SegmentContext& c, std::vector<RegionState>* regions, int id,
                  KeptPrices* kept) {
  const std::vector<int> smooth = SmoothVertices(c, (*regions)[id].vertices);
  if (smooth.size() < kMinRetypeVertices) return false;
  const TypedFit curved = DecideCurvedType(c, smooth, c.tolerance);
  if (curved.type == SurfaceType::kQuadric) return false;
  const SurfaceType types[] = {curved.type};
  return RetypeIfLowerKept(c, regions, id, types, kept);
}

std::vector<int> RetypeBentPlanes(const SegmentContext& c, std::vector<RegionState>* regions,
                                  KeptPrices* kept) {
  constexpr KeptPrices::Proposal kProposal = KeptPrices::kBentPlane;
  std::vector<int> retyped;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || r.type != SurfaceType::kPlane) continue;
    if (!Ask(*regions, id, kept, kProposal)) continue;
    const std::vector<int> smooth = SmoothVertices(c, r.vertices);
    if (smooth.size() >= kMinRetypeVertices &&
        !(FitFraction(c, r.surface, smooth, c.tolerance) > c.alpha) &&
        RetypeCurved(c, regions, id, kept)) {
      retyped.push_back(id);
    } else {
      Refused(*regions, id, kept, kProposal);
    }
  }
  return retyped;
}

namespace {

// The proposals of RetypeInaccurateCurved for region `id`, taken iff one
// lowers E; returns whether one was.
bool RetypeIfInaccurate(const SegmentContext& c, std::vector<RegionState>* regions, int id,
                        KeptPrices* kept) {
  const RegionState& r = (*regions)[id];
  const std::vector<int> smooth = SmoothVertices(c, r.vertices);
  if (smooth.size() < kMinRetypeVertices) return false;
  // A type with no valid fit left (a torus whose cusp the region grew
  // over) misses by any amount.
  const FitResult current = FitType(c, r.type, smooth);
  const double error = current.ok() ? ModelError(c, current) : HUGE_VAL;
  if (!(error > kInaccurateError * c.noise_sigma)) return false;
  // The proposals: the plane and the curved type of S1's order.
  const SurfaceType curved = DecideCurvedType(c, smooth, c.tolerance).type;
  std::vector<SurfaceType> types = {SurfaceType::kPlane};
  if (curved != SurfaceType::kQuadric) types.push_back(curved);
  return RetypeIfLowerKept(c, regions, id, types, kept);
}

}  // namespace

std::vector<int> RetypeInaccurateCurved(const SegmentContext& c,
                                        std::vector<RegionState>* regions, KeptPrices* kept) {
  constexpr KeptPrices::Proposal kProposal = KeptPrices::kInaccurateCurved;
  std::vector<int> retyped;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type)) continue;
    if (!Ask(*regions, id, kept, kProposal)) continue;
    if (RetypeIfInaccurate(c, regions, id, kept)) {
      retyped.push_back(id);
    } else {
      Refused(*regions, id, kept, kProposal);
    }
  }
  return retyped;
}

int RetypeToSimplerLimits(const SegmentContext& c, std::vector<RegionState>* regions,
                          KeptPrices* kept) {
  constexpr KeptPrices::Proposal kProposal = KeptPrices::kSimplerLimit;
  if (kept != nullptr) kept->Reserve(regions->size());
  std::vector<uint8_t> retyped(regions->size(), 0);
  // Each proposal reads and changes its own region (and `kept`'s entries
  // of it) only: concurrent.
  tbb::parallel_for(std::size_t{0}, regions->size(), [&](std::size_t k) {
    const int id = static_cast<int>(k);
    const RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type) || r.vertices.size() < kMinRetypeVertices) return;
    if (!Ask(*regions, id, kept, kProposal)) return;
    std::vector<SurfaceType> types = {SurfaceType::kPlane};
    if (r.type == SurfaceType::kCone) types.push_back(SurfaceType::kCylinder);
    retyped[id] = RetypeIfLowerKept(c, regions, id, types, kept);
    if (!retyped[id]) Refused(*regions, id, kept, kProposal);
  });
  return static_cast<int>(std::count(retyped.begin(), retyped.end(), 1));
}

}  // namespace meshseg::segment_internal
