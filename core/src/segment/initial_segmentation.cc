#include "segment/initial_segmentation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "meshseg/status_macros.h"
#include "segment/decide_type.h"
#include "segment/grow_region.h"
#include "segment/retype_by_interior.h"
#include "segment/seeds.h"

namespace meshseg::segment_internal {
namespace {

constexpr int kStopCheckEvery = 16;  // seeds between stop checks
// A curved region whose best analytic type fits at least this fraction
// (but not alpha) has grown past its surface, typically into a tangent
// plane: it keeps only the fitting vertices and regrows with that type.
constexpr double kTrimFraction = 0.75;
// Types a seed is grown with when its quadric region fits none, in the
// order of ALGORITHMS.md S1 step 2.5; a later type must grow this much
// larger to win.
constexpr std::array<SurfaceType, 5> kSeedTypes = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                                   SurfaceType::kSphere, SurfaceType::kCone,
                                                   SurfaceType::kTorus};
constexpr double kSeedTypeGain = 1.25;
constexpr int kTrimRounds = 4;
// A typed growth that stays near the seed's size found no surface.
constexpr std::size_t kMinSeedGrowth = 3;

// Keeps the piece of `vertices` holding the most of `seed` (a trim to the
// vertices a fit explains can cut a region in pieces) and frees the rest;
// keeps them all when none of them lies at the seed (nothing to choose by).
void KeepPieceHoldingSeed(const SegmentContext& c, std::span<const int> seed,
                          std::vector<int>* labels, std::vector<int>* vertices) {
  std::vector<int> piece = PieceHoldingSeed(c, *vertices, seed);
  if (piece.empty() || piece.size() == vertices->size()) return;
  const int id = (*labels)[piece.front()];
  for (const int v : *vertices) (*labels)[v] = -1;
  for (const int v : piece) (*labels)[v] = id;
  *vertices = std::move(piece);
}

// Grows `region` with the surface of `typed.type` and stores the result.
void GrowTyped(const SegmentContext& c, const TypedFit& typed, int id, std::vector<int>* labels,
               RegionState* region) {
  region->type = typed.type;
  region->surface = typed.fit.surface;
  SurfaceModel model(typed.type);
  if (GrowRegion(c, &model, c.tolerance, id, labels, &region->vertices)) {
    region->surface = model.fit().surface;
  }
}

// Grows `region` (its seed, labelled `id`) with the height function and,
// if that is a plane, as a plane. True if it is one and no curved type
// explains its interior kScoreMargin better; else its vertices are freed
// again and `region` holds all it reached.
bool GrowPlane(const SegmentContext& c, int id, std::vector<int>* labels, RegionState* region) {
  HeightModel height;
  GrowRegion(c, &height, c.tolerance, id, labels, &region->vertices);
  if (auto plane = PlaneIfFits(c, region->vertices, c.tolerance)) {
    GrowTyped(c, *plane, id, labels, region);
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, *labels, ids, region->vertices);
    if (interior.size() >= kMinInteriorVertices) {
      const double plane_score = ScoreType(c, SurfaceType::kPlane, interior).score;
      const auto curved = ScoreCurvedTypes(c, interior);
      if (std::none_of(curved.begin(), curved.end(),
                       [&](const ScoredFit& s) { return s.score + kScoreMargin < plane_score; })) {
        return true;
      }
    }
  }
  for (const int v : region->vertices) (*labels)[v] = -1;
  return false;
}

}  // namespace

void GrowAndType(const SegmentContext& c, int id, std::vector<int>* labels,
                 std::vector<RegionState>* regions) {
  RegionState& region = (*regions)[id];
  const std::vector<int> seed = region.vertices;
  HeightModel height;
  GrowRegion(c, &height, c.tolerance, id, labels, &region.vertices);
  // ALGORITHMS.md S1 step 2.3: a plane if alpha of the vertices fit one.
  if (auto plane = PlaneIfFits(c, region.vertices, c.tolerance)) {
    GrowTyped(c, *plane, id, labels, &region);
    return;
  }
  // Step 4: grow on with the general quadric; step 5: decide the type.
  SurfaceModel quadric(SurfaceType::kQuadric);
  GrowRegion(c, &quadric, c.tolerance, id, labels, &region.vertices);
  // The height function may have stopped short of a plane's area (noise
  // at its sharp rims); the quadric's region gets the plane test again
  // before any curved type (a huge-radius cylinder fits a plane as well).
  if (auto plane = PlaneIfFits(c, region.vertices, c.tolerance)) {
    GrowTyped(c, *plane, id, labels, &region);
    return;
  }
  // DecideCurvedType falls back to the quadric when no analytic type fits
  // any vertex; here that is no answer yet (the quadric may have grown over
  // two planes and their fillet, a product of planes fitting all three), so
  // it goes on to the seed's own analytic trials below.
  TypedFit typed = DecideCurvedType(c, region.vertices, c.tolerance);
  const bool analytic = typed.type != SurfaceType::kQuadric;
  if (analytic && typed.fraction > c.alpha) {
    GrowTyped(c, typed, id, labels, &region);
    return;
  }
  if (analytic && typed.fraction >= kTrimFraction) {
    std::erase_if(region.vertices, [&](int v) {
      if (Fits(c, v, ProjectVertex(c, typed.fit.surface, v), c.tolerance)) return false;
      (*labels)[v] = -1;
      return true;
    });
    KeepPieceHoldingSeed(c, seed, labels, &region.vertices);
    // The type is decided again on what is left: it may be a plane the
    // curved fit bent over to reach a tangent fillet's first rows, or a
    // narrow chamfer that the cone fits better once its rims are gone.
    if (auto plane = PlaneIfFits(c, region.vertices, c.tolerance)) {
      typed = *plane;
    } else if (TypedFit again = DecideCurvedType(c, region.vertices, c.tolerance);
               again.type != SurfaceType::kQuadric && again.fraction > c.alpha) {
      typed = std::move(again);
    }
    GrowTyped(c, typed, id, labels, &region);
    return;
  }
  // The quadric has bent over a tangent boundary (a fillet and its plane):
  // no analytic type fits the whole, and the seed is too small to tell the
  // type. The seed is grown with each analytic type alone; the largest
  // result that passes alpha wins (fewer parameters on near-ties).
  const std::vector<int> quadric_vertices = region.vertices;
  for (const int v : quadric_vertices) (*labels)[v] = -1;
  std::optional<RegionState> best;
  for (const SurfaceType type : kSeedTypes) {
    // Two starts: the seed, and the quadric region trimmed to the vertices
    // a fit of `type` explains (refitted a few times, a robust fit of the
    // region's dominant surface).
    for (int start = 0; start < 2; ++start) {
      std::vector<int> from = seed;
      TypedFit typed;
      typed.type = type;
      typed.fit = FitType(c, type, start == 0 ? seed : quadric_vertices);
      for (int k = 0; start == 1 && typed.fit.ok() && k < kTrimRounds; ++k) {
        from = FittingVertices(c, typed.fit.surface, quadric_vertices);
        if (from.size() < seed.size()) break;
        typed.fit = FitType(c, type, from);
      }
      // The trial starts from the piece of them at the seed, cut only once
      // the fit has settled: an early fit is off where the quadric bent away,
      // and the piece of its vertices at the seed can be smaller than the
      // seed (on a small flat top of a conical frustum at sigma = 0.15 h, 10
      // of the 14 seed vertices).
      if (start == 1 && typed.fit.ok() && from.size() >= seed.size()) {
        const std::size_t fitted = from.size();
        from = PieceHoldingSeed(c, from, seed);
        if (from.size() >= seed.size() && from.size() < fitted) typed.fit = FitType(c, type, from);
      }
      if (!typed.fit.ok() || from.size() < seed.size()) continue;
      RegionState trial{.type = type, .surface = typed.fit.surface, .vertices = from, .alive = true};
      for (const int v : from) (*labels)[v] = id;
      GrowTyped(c, typed, id, labels, &trial);
      for (int k = 0; k < kTrimRounds; ++k) {
        const double f = FitFraction(c, trial.surface, trial.vertices, c.tolerance);
        if (f > c.alpha || f < kTrimFraction) break;
        std::erase_if(trial.vertices, [&](int v) {
          if (Fits(c, v, ProjectVertex(c, trial.surface, v), c.tolerance)) return false;
          (*labels)[v] = -1;
          return true;
        });
        KeepPieceHoldingSeed(c, seed, labels, &trial.vertices);
        typed.fit.surface = trial.surface;
        GrowTyped(c, typed, id, labels, &trial);
      }
      for (const int v : trial.vertices) (*labels)[v] = -1;
      if (FitFraction(c, trial.surface, trial.vertices, c.tolerance) <= c.alpha) continue;
      if (!best || trial.vertices.size() > kSeedTypeGain * best->vertices.size()) {
        best = std::move(trial);
      }
    }
  }
  if (best && best->vertices.size() >= kMinSeedGrowth * seed.size()) {
    region = std::move(*best);
    for (const int v : region.vertices) (*labels)[v] = id;
    // A torus or cone of huge radius found this way may be a plane: plane
    // comes first in S1's order (step 2.3 before 2.5).
    if (region.type != SurfaceType::kPlane) {
      if (auto plane = PlaneIfFits(c, region.vertices, c.tolerance)) {
        GrowTyped(c, *plane, id, labels, &region);
      }
    }
    return;
  }
  for (const int v : quadric_vertices) (*labels)[v] = id;
  region.type = SurfaceType::kQuadric;
  region.surface = FitType(c, SurfaceType::kQuadric, region.vertices).surface;
}

absl::Status GrowPlanesFirst(const SegmentContext& c, const std::vector<int>& order,
                             std::vector<int>* labels, std::vector<RegionState>* regions) {
  std::vector<uint8_t> tried(c.vertex_count(), 0);
  NeighborhoodScratch scratch;
  int count = 0;
  for (const int i : order) {
    if ((*labels)[i] != -1 || tried[i]) continue;
    tried[i] = 1;
    if (++count % kStopCheckEvery == 0) MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
    std::vector<int> seed = CollectSeed(c, i, *labels, &scratch);
    if (seed.empty() || !PlaneIfFits(c, seed, c.tolerance)) continue;
    const int id = static_cast<int>(regions->size());
    for (const int v : seed) (*labels)[v] = id;
    RegionState region{.type = SurfaceType::kPlane,
                       .surface = Plane{},
                       .vertices = std::move(seed),
                       .alive = true};
    if (GrowPlane(c, id, labels, &region)) {
      regions->push_back(std::move(region));
    } else {
      for (const int v : region.vertices) tried[v] = 1;
    }
  }
  return absl::OkStatus();
}

absl::Status GrowInitialRegions(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions) {
  const std::vector<int> order = SeedOrder(c);
  if (c.noise_sigma > 0.0) MESHSEG_RETURN_IF_ERROR(GrowPlanesFirst(c, order, labels, regions));
  NeighborhoodScratch scratch;
  std::size_t labelled = 0;
  for (const RegionState& plane : *regions) labelled += plane.vertices.size();
  int tried = 0;
  for (const int i : order) {
    if ((*labels)[i] != -1) continue;
    if (++tried % kStopCheckEvery == 0) {
      MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
      c.run->Progress("segment", 0.6 * labelled / c.vertex_count());
    }
    std::vector<int> seed = CollectSeed(c, i, *labels, &scratch);
    if (seed.empty()) continue;
    const int id = static_cast<int>(regions->size());
    for (const int v : seed) (*labels)[v] = id;
    regions->push_back(RegionState{.type = SurfaceType::kQuadric,
                                   .surface = Quadric{},
                                   .vertices = std::move(seed),
                                   .alive = true});
    GrowAndType(c, id, labels, regions);
    labelled += (*regions)[id].vertices.size();
  }
  return absl::OkStatus();
}

}  // namespace meshseg::segment_internal
