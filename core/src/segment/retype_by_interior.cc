#include "segment/retype_by_interior.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/retype_coaxial_bands.h"

namespace meshseg::segment_internal {
namespace {

// A type fits "near the noise and far closer" than the region's own at
// this share of its model error and at most this many sigmas.
constexpr double kCloserError = 0.5;
constexpr double kNearNoiseError = 1.0;

// Of `scored`, the limit of `general` (IsLimitOf) with the fewest parameters
// whose model error is at most `max_error` and score at most `max_score`.
const ScoredFit* SimplestLimit(const SegmentContext& c, std::span<const ScoredFit> scored,
                               SurfaceType general, double max_error, double max_score) {
  const ScoredFit* simplest = nullptr;
  for (const ScoredFit& s : scored) {
    if (!IsLimitOf(s.type, general) || !s.fit.ok() || !(ModelError(c, s.fit) <= max_error) ||
        !(s.score <= max_score)) {
      continue;
    }
    if (simplest == nullptr || ParameterCount(s.type) < ParameterCount(simplest->type)) {
      simplest = &s;
    }
  }
  return simplest;
}

// The curved type to give a region of type `own` with interior `interior`,
// and its fit there: the simplest limit of `own` (IsLimitOf) that fits at
// the noise and scores within kScoreMargin of the best type, since a more
// general model beats its own limit by chance (on a noisy countersink band
// a torus came 0.011 sigma closer than the cone, 0.997 against 1.008, and
// scored 0.9 lower); else the best type if it scores kScoreMargin below
// `own`, or the simplest limit of that type chosen the same way; else `own`.
// `own` scores at most `own_on_axis` (its score with its axis shared,
// infinite if it has no such fit).
SurfaceType BestInteriorType(const SegmentContext& c, SurfaceType own, double own_on_axis,
                             const std::vector<int>& interior, FitResult* interior_fit) {
  const auto scored = ScoreCurvedTypes(c, interior);
  // Some type must fit at the noise, or near it and either far closer than
  // `own` (a countersink band grown as a torus 3.26 sigma off, where the
  // cone meets it at 0.28) or scoring kScoreMargin below it (a 45-degree
  // chamfer band grown as a sphere 0.49 sigma off, where the cone meets it
  // at 0.26 sigma and scores 70 lower), or a limit of
  // `own` scoring less than kScoreMargin above it, within kScoredNearError
  // (own's extra parameters must buy kScoreMargin): a round of a part
  // reconstructed from points, 0.85 sigma off its cylinder, would go to a
  // torus 0.71 off that follows the reconstruction's error.
  double limit = kMinModelError * c.noise_sigma;
  double own_score = std::numeric_limits<double>::infinity();
  for (const ScoredFit& s : scored) {
    if (s.type != own || !s.fit.ok()) continue;
    limit = std::max(limit, std::min(kCloserError * ModelError(c, s.fit),
                                     kNearNoiseError * c.noise_sigma));
    own_score = s.score;
  }
  // A cone on the axis of the turned face beside it is its own type with 4
  // parameters fewer: the type it must lose to.
  own_score = std::min(own_score, own_on_axis);
  if (std::none_of(scored.begin(), scored.end(), [&](const ScoredFit& s) {
        if (!s.fit.ok()) return false;
        const double e = ModelError(c, s.fit);
        return e <= limit || TakesOverNearTheNoise(c, s.type, e, s.score, own, own_score);
      })) {
    return own;
  }
  const ScoredFit* best = &scored.front();
  for (const ScoredFit& s : scored) {
    if (s.score < best->score) best = &s;
  }
  const double at_noise = kMinModelError * c.noise_sigma;
  // The simplest special case of `own` that does as well; or, near the
  // noise, that scores less than kScoreMargin above `own`: its extra
  // parameters buy too little (on noisy countersink bands the torus and the
  // cone both meet the interior at ~0.4 sigma, and their scores differ by
  // one or two units either way: torus 0.39, cone 0.40 and 2.6 lower, or
  // torus 0.38, cone 0.40 and 1.3 higher).
  const ScoredFit* simplest =
      SimplestLimit(c, scored, own, at_noise, best->score + kScoreMargin);
  if (simplest == nullptr) {
    simplest = SimplestLimit(c, scored, own, kScoredNearError * c.noise_sigma,
                             own_score + kScoreMargin);
  }
  if (simplest != nullptr) {
    *interior_fit = simplest->fit;
    return simplest->type;
  }
  if (!(best->score + kScoreMargin < own_score)) return own;
  // The best type may itself beat its own limit by chance (a countersink
  // band grown as a sphere, whose interior scores torus -1295.7 and cone
  // -1294.2, both at the noise: the cone is the surface).
  if (const ScoredFit* limit_of_best =
          SimplestLimit(c, scored, best->type, at_noise, best->score + kScoreMargin)) {
    best = limit_of_best;
  }
  *interior_fit = best->fit;
  return best->type;
}

// The curved type to give a region of type `own` with vertices `vertices`
// whose vertices lie on facets (SegmentParams::on_facets), and its fit
// there: the type of lowest InformationScore over all of them if it
// scores kScoreMargin below `own`, or its simplest limit scoring within
// kScoreMargin of it; else `own`. All of the vertices: without noise the
// rims are as true as the interior, and on a narrow band they are what
// tells a sphere from a cylinder (a CAD tessellation's corner rounds of
// r 25.4, 4 edges high: on the interior the cylinder misses by 0.067 and
// the sphere by 0.072; on all of it by 0.076 and 0.096).
SurfaceType BestTypeOnFacets(const SegmentContext& c, SurfaceType own,
                             std::span<const int> vertices, FitResult* fit) {
  const auto scored = ScoreCurvedTypes(c, vertices);
  const ScoredFit* best = &scored.front();
  double own_score = std::numeric_limits<double>::infinity();
  for (const ScoredFit& s : scored) {
    if (s.score < best->score) best = &s;
    if (s.type == own) own_score = s.score;
  }
  if (!(best->score + kScoreMargin < own_score)) return own;
  if (const ScoredFit* limit =
          SimplestLimit(c, scored, best->type, std::numeric_limits<double>::infinity(),
                        best->score + kScoreMargin)) {
    best = limit;
  }
  *fit = best->fit;
  return best->type;
}

}  // namespace

std::vector<int> InteriorVertices(const SegmentContext& c, const std::vector<int>& labels,
                                  std::span<const int> ids, std::span<const int> vertices) {
  std::vector<int> interior;
  for (const int v : vertices) {
    const auto around = c.graph.Neighbors(v);
    if (std::all_of(around.begin(), around.end(), [&](int u) {
          return std::find(ids.begin(), ids.end(), labels[u]) != ids.end();
        })) {
      interior.push_back(v);
    }
  }
  return interior;
}

bool TypeMissesInterior(const SegmentContext& c, const std::vector<int>& labels, int id,
                        const RegionState& r) {
  const int ids[] = {id};
  const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
  return interior.size() >= kMinInteriorVertices && !FitsAtNoise(c, FitType(c, r.type, interior));
}

std::vector<int> RetypeByInterior(const SegmentContext& c, const std::vector<int>& labels,
                                  std::vector<RegionState>* regions) {
  // On a noise-free mesh nothing fits "at the noise"; on facets see above.
  if (!(c.noise_sigma > 0.0) && !c.on_facets) return {};
  const int n_regions = static_cast<int>(regions->size());
  std::vector<uint8_t> retyped(n_regions, 0);
  // The score of each cone region's interior on a turned neighbour's axis
  // (BestCoaxialCone) where that cone meets it within kScoredNearError
  // sigmas, read before any region changes.
  std::vector<double> on_axis(n_regions, std::numeric_limits<double>::infinity());
  tbb::parallel_for(0, n_regions, [&](int id) {
    const RegionState& r = (*regions)[id];
    if (c.on_facets || !r.alive || r.type != SurfaceType::kCone) return;
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
    if (interior.size() < kMinInteriorVertices) return;
    const auto cone = BestCoaxialCone(c, labels, *regions, id, interior);
    if (cone && ModelErrorOfMeanSquare(c, cone->mean_square) <= kScoredNearError * c.noise_sigma) {
      on_axis[id] = cone->score;
    }
  });
  tbb::parallel_for(0, n_regions, [&](int id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type)) return;
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
    if (interior.size() < kMinInteriorVertices) return;
    FitResult interior_fit;
    const SurfaceType type = c.on_facets
                                 ? BestTypeOnFacets(c, r.type, r.vertices, &interior_fit)
                                 : BestInteriorType(c, r.type, on_axis[id], interior, &interior_fit);
    if (type == r.type) return;
    // On facets the fit was already made to all of the region's vertices.
    const FitResult whole = c.on_facets ? interior_fit : FitType(c, type, r.vertices);
    r.type = type;
    r.surface = whole.ok() ? whole.surface : interior_fit.surface;
    retyped[id] = 1;
  });
  std::vector<int> ids;
  for (int id = 0; id < n_regions; ++id) {
    if (retyped[id]) ids.push_back(id);
  }
  return ids;
}

absl::StatusOr<std::vector<int>> RetypeByInteriorAndExpand(const SegmentContext& c,
                                                           std::vector<int>* labels,
                                                           std::vector<RegionState>* regions) {
  std::vector<int> retyped = RetypeByInterior(c, *labels, regions);
  if (!retyped.empty()) MESHSEG_RETURN_IF_ERROR(ExpandRegions(c, labels, regions).status());
  return retyped;
}

}  // namespace meshseg::segment_internal
