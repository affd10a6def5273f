// The type decision of ALGORITHMS.md S1 steps 2.3 and 2.5: the first
// analytic type whose fit meets (5) and (6) at more than alpha of the
// region's vertices.
#ifndef MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_
#define MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

struct TypedFit {
  SurfaceType type = SurfaceType::kQuadric;
  FitResult fit;
  double fraction = 0.0;  // of the vertices meeting (5) and (6)
};

// The fit of `type` to `vertices` and the fraction of them meeting (5) and
// (6) for it (0 if the fit is invalid).
TypedFit TryType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices,
                 const Tolerance& tol);

// A model error sqrt(rms^2 - sigma^2) at or under this many noise sigmas is
// a fit at the noise.
inline constexpr double kMinModelError = 0.25;

// A model error at or under this many noise sigmas is near the noise: a
// fit there may replace another if the scores say so (RetypeByInterior).
inline constexpr double kScoredNearError = 0.5;

// How far `fit` misses its vertices beyond the noise, sqrt(rms^2 - sigma^2).
// At sigma = 0.15 h the rms of a sphere on a narrow 45-degree chamfer is
// only 10 % above the cone's, which sits at the noise; their model errors
// are 0.45 sigma and 0.
double ModelError(const SegmentContext& c, const FitResult& fit);
// The same for residuals of mean square `mean_square`.
double ModelErrorOfMeanSquare(const SegmentContext& c, double mean_square);

// True if `fit` is valid and meets its vertices at the noise: model error
// at or under kMinModelError sigmas.
bool FitsAtNoise(const SegmentContext& c, const FitResult& fit);
// True if `fit` is valid and meets its vertices near the noise: model error
// at or under kScoredNearError sigmas.
bool FitsNearNoise(const SegmentContext& c, const FitResult& fit);

// Free parameters of a type's surface: plane 3, sphere 4, cylinder 5,
// cone 6, torus 7, general quadric 9 (10 coefficients up to scale); 0 for
// freeform.
int ParameterCount(SurfaceType type);

// True if `special` is a limit of `general` with fewer parameters, in the
// family of surfaces around an axis: a cylinder is a cone of half-angle 0,
// and both are tori of infinite minor radius. (A sphere is a torus of major
// radius 0, but a narrow band of cone fits a sphere about as well as a
// torus does: that is no sign of a sphere.)
bool IsLimitOf(SurfaceType special, SurfaceType general);

// The Bayesian information criterion, for normal residuals of unknown
// variance, of a model with `parameters` free parameters whose `count`
// residuals have mean square `mean_square`: m ln(mean_square) +
// parameters ln(m), m = min(count, kMaxSample) (our addition, where the
// tolerances cannot tell types apart). Fits see at most kMaxSample
// residuals; counting all of a large region's would also make the
// meshing's correlated residuals decisive. The variance is the model's own,
// not the noise estimate, which a region's local noise can miss by 5 %;
// but a mean square under (kMinModelError sigma)^2 counts as that much: on
// an exact CAD mesh a cylinder and a cone of half-angle 0 both fit to
// rounding, and the log of rounding errors would pick either.
// One model is taken over another only if it scores kScoreMargin less: a
// likelihood ratio of e^5, where a type that fits the same points only by
// chance gains about its extra parameter count.
double InformationScore(const SegmentContext& c, double mean_square, std::size_t count,
                        int parameters);
inline constexpr double kScoreMargin = 10.0;

// True if a fit of `type`, `model_error` (ModelError) off its vertices and
// scoring `score` there, may take over from the type `own` scoring
// `own_score` on the same vertices as a fit near the noise: within
// kScoredNearError sigmas, and kScoreMargin below `own`, or, if it is a
// limit of `own` (IsLimitOf), less than kScoreMargin above it (own's extra
// parameters must buy that much).
bool TakesOverNearTheNoise(const SegmentContext& c, SurfaceType type, double model_error,
                           double score, SurfaceType own, double own_score);

// A fit of one type to a vertex set with its InformationScore there
// (infinite if the fit is invalid).
struct ScoredFit {
  SurfaceType type = SurfaceType::kQuadric;
  FitResult fit;
  double score = std::numeric_limits<double>::infinity();
};
ScoredFit ScoreType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices);

// The curved types in ALGORITHMS.md S1's order (step 2.5), then S2's torus.
inline constexpr std::array<SurfaceType, 4> kCurvedTypes = {
    SurfaceType::kCylinder, SurfaceType::kSphere, SurfaceType::kCone, SurfaceType::kTorus};

// The ScoreType of lowest score on `vertices` of a plane and each of
// kCurvedTypes (its fit invalid if none is valid).
ScoredFit BestScoredType(const SegmentContext& c, std::span<const int> vertices);

// For region `r` whose type has no valid fit to its vertices: the
// BestScoredType there, if it scores kScoreMargin below r's surface
// (InformationScore, with r's type's parameter count). A region keeps the
// surface it grew with until a refit; when its vertices change so much that
// its type no longer fits them, that surface can miss them by far (a torus
// grown on the crease ring between a small plane disc and the conical
// frustum under it, at sigma = 0.15 h, that took most of the disc from the
// leftovers: 5 sigma), or still meet them better than any other type (a
// torus blend band on a noisy CAD mesh whose torus fit fails for a while: a
// cylinder would miss it by 1.3 sigma, the torus by 0.5).
std::optional<ScoredFit> TypeThatFitsInstead(const SegmentContext& c, const RegionState& r);

// ScoreType of each of kCurvedTypes on `vertices`.
std::array<ScoredFit, kCurvedTypes.size()> ScoreCurvedTypes(const SegmentContext& c,
                                                            std::span<const int> vertices);

// Returns the plane fit of `vertices` if it passes the alpha test.
std::optional<TypedFit> PlaneIfFits(const SegmentContext& c, std::span<const int> vertices,
                                    const Tolerance& tol);

// Returns the first of cylinder, sphere, cone, torus passing the alpha test
// (the cone replacing the cylinder only when clearly more accurate); if none
// passes, the one with the largest fitting fraction (earlier types winning
// near-ties), or the general quadric if no analytic type fits any vertex.
TypedFit DecideCurvedType(const SegmentContext& c, std::span<const int> vertices,
                          const Tolerance& tol);

// True if `surface` (a cylinder, sphere, cone or torus fitted to `vertices`
// with residual `rms`) bends less than the tolerances over the region: its
// sagitta D^2 / 2R across the region's radius D (measured across the
// rulings of a cylinder or cone) is under th_dis (or twice the fit's own rms
// scatter) and its normal turns by less than th_nm (D / R).
// Such a fit passes the alpha test only by fitting noise a plane leaves just
// outside th_dis (a reconstructed flat face came out as a cylinder of radius
// 914 mm). False for planes and quadrics.
bool NearlyFlat(const SegmentContext& c, const Surface& surface, double rms,
                std::span<const int> vertices, const Tolerance& tol);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_
