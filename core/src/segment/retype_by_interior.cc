#include "segment/retype_by_interior.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
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

// The curved type to propose for a region of type `own` with interior
// `interior`, and its fit there: the simplest limit of `own` (IsLimitOf)
// that fits at the noise and scores within kScoreMargin of the best type,
// since a more general model beats its own limit by chance (on a noisy
// countersink band a torus came 0.011 sigma closer than the cone, 0.997
// against 1.008, and scored 0.9 lower); else the best type if it scores
// kScoreMargin below `own`, or the simplest limit of that type chosen the
// same way; else another type as good at the noise (OtherTypeAtTheNoise);
// else `own`. `own` scores at most `own_on_axis` (its score with its axis
// shared, infinite if it has no such fit).
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
  if (!(best->score + kScoreMargin < own_score)) {
    // Two unrelated types both at the noise: the interior cannot tell them
    // apart, and only the labelling each places can (PEARL compares models
    // from labellings placed for them). The other is proposed, for E to
    // price with the expansion it enables.
    const ScoredFit* other = OtherTypeAtTheNoise(c, scored, own, own_score);
    if (other == nullptr) return own;
    *interior_fit = other->fit;
    return other->type;
  }
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

bool Nested(SurfaceType a, SurfaceType b) {
  const auto sphere_of_torus = [](SurfaceType x, SurfaceType y) {
    return x == SurfaceType::kSphere && y == SurfaceType::kTorus;
  };
  return IsLimitOf(a, b) || IsLimitOf(b, a) || sphere_of_torus(a, b) || sphere_of_torus(b, a);
}

const ScoredFit* OtherTypeAtTheNoise(const SegmentContext& c, std::span<const ScoredFit> scored,
                                     SurfaceType own, double own_score) {
  if (std::none_of(scored.begin(), scored.end(), [&](const ScoredFit& s) {
        return s.type == own && FitsAtNoise(c, s.fit);
      })) {
    return nullptr;
  }
  const ScoredFit* other = nullptr;
  for (const ScoredFit& s : scored) {
    if (s.type == own || Nested(s.type, own) || !FitsAtNoise(c, s.fit) ||
        !(s.score < own_score + kScoreMargin)) {
      continue;
    }
    if (other == nullptr || s.score < other->score) other = &s;
  }
  return other;
}

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

std::vector<InteriorRetype> ProposeInteriorTypes(const SegmentContext& c,
                                                 const std::vector<int>& labels,
                                                 const std::vector<RegionState>& regions,
                                                 KeptPrices* kept) {
  constexpr KeptPrices::Proposal kProposal = KeptPrices::kInteriorType;
  // On a noise-free mesh nothing fits "at the noise"; on facets see above.
  if (!(c.noise_sigma > 0.0) && !c.on_facets) return {};
  const int n_regions = static_cast<int>(regions.size());
  if (kept != nullptr) kept->Reserve(regions.size());
  std::vector<std::optional<InteriorRetype>> proposed(n_regions);
  // Each region's proposal reads the labels and regions as given and writes
  // its own entries (of `proposed`, and `kept`'s): concurrent.
  tbb::parallel_for(0, n_regions, [&](int id) {
    const RegionState& r = regions[id];
    if (!r.alive || !IsCurved(r.type)) return;
    // A cone's own score reads its neighbours (BestCoaxialCone): asked
    // every time; every other region's proposal reads the region alone.
    const bool alone = c.on_facets || r.type != SurfaceType::kCone;
    if (alone && kept != nullptr && kept->Refused(regions, id, kProposal)) return;
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
    FitResult interior_fit;
    SurfaceType type = r.type;
    if (interior.size() >= kMinInteriorVertices) {
      // The score of a cone region's interior on a turned neighbour's axis
      // (BestCoaxialCone) where that cone meets it within kScoredNearError
      // sigmas.
      double on_axis = std::numeric_limits<double>::infinity();
      if (!alone) {
        const auto cone = BestCoaxialCone(c, labels, regions, id, interior);
        if (cone &&
            ModelErrorOfMeanSquare(c, cone->mean_square) <= kScoredNearError * c.noise_sigma) {
          on_axis = cone->score;
        }
      }
      type = c.on_facets ? BestTypeOnFacets(c, r.type, r.vertices, &interior_fit)
                         : BestInteriorType(c, r.type, on_axis, interior, &interior_fit);
    }
    if (type == r.type) {
      if (alone && kept != nullptr) kept->Refuse(regions, id, kProposal);
      return;
    }
    // A cone beside a turned face whose axis it shares is proposed on that
    // axis, its label counting only its own parameters (energy.h, "Shared
    // parameters"); the re-estimation frees it where its data pays for that.
    if (type == SurfaceType::kCone && !c.on_facets) {
      if (const auto cone = BestCoaxialCone(c, labels, regions, id, Sample(interior))) {
        const RegionState on_axis = CoaxialConeRegion(r, cone->fit.surface);
        proposed[id] = InteriorRetype{.id = id,
                                      .type = type,
                                      .surface = on_axis.surface,
                                      .shared_parameters = on_axis.shared_parameters};
        return;
      }
    }
    // On facets the fit was already made to all of the region's vertices.
    const FitResult whole = c.on_facets ? interior_fit : FitType(c, type, r.vertices);
    proposed[id] = InteriorRetype{
        .id = id, .type = type, .surface = whole.ok() ? whole.surface : interior_fit.surface};
  });
  std::vector<InteriorRetype> proposals;
  for (auto& p : proposed) {
    if (p) proposals.push_back(std::move(*p));
  }
  return proposals;
}

absl::StatusOr<std::vector<int>> RetypeByInterior(const SegmentContext& c,
                                                  std::vector<int>* labels,
                                                  std::vector<RegionState>* regions,
                                                  KeptPrices* kept) {
  std::vector<int> retyped;
  const std::vector<InteriorRetype> proposals = ProposeInteriorTypes(c, *labels, *regions, kept);
  if (proposals.empty()) return retyped;
  double energy = TotalEnergy(c, *labels, *regions);
  for (const InteriorRetype& p : proposals) {
    // An earlier accepted proposal's expansion may have emptied this region.
    if (!(*regions)[p.id].alive || (*regions)[p.id].vertices.empty()) continue;
    // The retype, re-estimated, then the expansion.
    RegionState r = (*regions)[p.id];
    r.type = p.type;
    r.surface = p.surface;
    r.shared_parameters = p.shared_parameters;
    MESHSEG_ASSIGN_OR_RETURN(Placed next,
                             PlacedByExpansion(c, *labels, *regions, p.id, Reestimated(c, r)));
    if (!(next.energy < energy)) continue;
    *labels = std::move(next.labels);
    *regions = std::move(next.regions);
    energy = next.energy;
    retyped.push_back(p.id);
  }
  return retyped;
}

}  // namespace meshseg::segment_internal
