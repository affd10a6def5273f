#include "segment/merge_same_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "segment/decide_type.h"
#include "segment/region_graph.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

constexpr std::array<SurfaceType, 5> kAnalyticTypes = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                                       SurfaceType::kSphere, SurfaceType::kCone,
                                                       SurfaceType::kTorus};

// A merge TestUnion accepts.
struct UnionTest {
  double gain = 0.0;  // score of two surfaces minus score of one
  SurfaceType type = SurfaceType::kQuadric;
};

// The residual sum of squares of `part` (of region `r`) under a fit of r's
// type to it; under r's own surface if that fit fails (a torus on a narrow
// piece of band).
double SumOfSquares(const SegmentContext& c, const RegionState& r, const std::vector<int>& part) {
  const FitResult fit = FitType(c, r.type, part);
  if (fit.ok()) return part.size() * fit.rms_distance * fit.rms_distance;
  return SquaredDistances(c, r.surface, part);
}

std::optional<UnionTest> TestUnion(const SegmentContext& c, const std::vector<int>& labels,
                                   int a, int b, const std::vector<RegionState>& regions) {
  const int ids[] = {a, b};
  const std::vector<int> part_a = InteriorVertices(c, labels, ids, regions[a].vertices);
  const std::vector<int> part_b = InteriorVertices(c, labels, ids, regions[b].vertices);
  if (part_a.size() < kMinInteriorVertices || part_b.size() < kMinInteriorVertices) {
    return std::nullopt;
  }
  std::vector<int> both = part_a;
  both.insert(both.end(), part_b.begin(), part_b.end());
  std::sort(both.begin(), both.end());
  const SurfaceType type_a = regions[a].type;
  const SurfaceType type_b = regions[b].type;
  const double squares_a = SumOfSquares(c, regions[a], part_a);
  const double squares_b = SumOfSquares(c, regions[b], part_b);
  // A plane part whose principal curvatures are a curved face's
  // (CurvedField) is a strip of its curved neighbour that a plane fits
  // within the tolerances (a 60-degree round of r 4 between two planes at
  // sigma = 0.15 h: 67 interior vertices, where the information criterion
  // cannot tell a narrow plane from a narrow cylinder): the pair merges,
  // first, if the neighbour's type meets the union at the noise, or as
  // closely as the plane meets the strip (quarter rounds of r 5 and 6 on
  // the convex edges of a block at sigma = 0.15 h, on two noise draws: the
  // cylinder 0.28 and 0.44 sigma off the union, the plane 0.33 and 0.58 off
  // its strip).
  std::optional<SurfaceType> strip_of;
  double strip_mean_square = 0.0;
  if (type_a == SurfaceType::kPlane && IsCurved(type_b) && CurvedField(c, part_a)) {
    strip_of = type_b;
    strip_mean_square = squares_a / part_a.size();
  }
  if (type_b == SurfaceType::kPlane && IsCurved(type_a) && CurvedField(c, part_b)) {
    strip_of = type_a;
    strip_mean_square = squares_b / part_b.size();
  }
  if (strip_of) {
    const FitResult fit = FitType(c, *strip_of, both);
    if (fit.ok() && ModelError(c, fit) <= std::max(kMinModelError * c.noise_sigma,
                                                   ModelErrorOfMeanSquare(c, strip_mean_square))) {
      return UnionTest{.gain = std::numeric_limits<double>::max(), .type = *strip_of};
    }
  }
  const double squares = squares_a + squares_b;
  // One surface must meet the union at the noise, or as closely as the
  // closer of the two parts' own surfaces meets its part, or, near the
  // noise, as the farther one does (a 45-degree countersink band at
  // sigma = 0.15 h: a sphere piece 0.39 sigma off, a cone piece 0.22, one
  // cone 0.34 off the union and 17 better).
  const double mean_square_a = squares_a / part_a.size();
  const double mean_square_b = squares_b / part_b.size();
  const double closer = ModelErrorOfMeanSquare(c, std::min(mean_square_a, mean_square_b));
  const double farther = ModelErrorOfMeanSquare(c, std::max(mean_square_a, mean_square_b));
  const double error_limit = std::max({kMinModelError * c.noise_sigma, closer,
                                       std::min(farther, kScoredNearError * c.noise_sigma)});
  const double two = InformationScore(c, squares / both.size(), both.size(),
                                      ParameterCount(type_a) + ParameterCount(type_b));
  // A surface that meets the union at the noise and misses it by at most
  // kScoredNearError sigma more than the two parts' own surfaces miss them
  // is one surface at this noise, whatever the scores say: they count the
  // meshing's own bias (a 45-degree countersink band at sigma = 0.15 h: a
  // piece of 85 interior vertices 0.5 sigma outside the true cone on one
  // side of the voxel grid; one cone 0.15 sigma off the union, 0.33 sigma
  // more than the two pieces' cones, and 10.6 worse).
  const double max_excess = kScoredNearError * c.noise_sigma;
  std::vector<UnionTest> passing;
  for (const SurfaceType type : kAnalyticTypes) {
    const FitResult fit = FitType(c, type, both);
    if (!fit.ok() || !(ModelError(c, fit) <= error_limit)) continue;
    const double gain = two - InformationScore(c, fit.rms_distance * fit.rms_distance, both.size(),
                                               ParameterCount(type));
    // One surface near the noise is the simpler account of both parts: they
    // stay apart only if two surfaces score kScoreMargin better, as a limit
    // type takes over near the noise (TakesOverNearTheNoise) (a 45-degree
    // countersink band at sigma = 0.15 h in a sphere piece and a cone piece,
    // each at the noise, the cone 0.08 sigma off the union and 7.0 worse; a
    // 60-degree round of r 4 between two planes at sigma = 0.15 h in two
    // plane strips, 0.17 and 0.35 sigma off theirs, one cylinder 0.27 sigma
    // off and 8.0 better).
    const double needed = FitsNearNoise(c, fit) ? -kScoreMargin : kScoreMargin;
    const double excess_square = fit.rms_distance * fit.rms_distance - squares / both.size();
    if (gain > needed || (FitsAtNoise(c, fit) && excess_square <= max_excess * max_excess)) {
      passing.push_back(UnionTest{.gain = gain, .type = type});
    }
  }
  if (passing.empty()) return std::nullopt;
  const UnionTest* best = &passing.front();
  for (const UnionTest& t : passing) {
    if (t.gain > best->gain) best = &t;
  }
  // Its simplest limit if that gains within kScoreMargin as much, as in
  // RetypeByInterior: a cone beats its cylinder by chance (a half-cylinder
  // groove of r 7 across a plane face at sigma = 0.15 h, with a plane strip
  // of it: cone 67.5, cylinder 63.8).
  const UnionTest* simplest = best;
  for (const UnionTest& t : passing) {
    if (IsLimitOf(t.type, best->type) && t.gain + kScoreMargin > best->gain &&
        ParameterCount(t.type) < ParameterCount(simplest->type)) {
      simplest = &t;
    }
  }
  return *simplest;
}

}  // namespace

absl::StatusOr<int> MergeSameSurface(const SegmentContext& c, std::vector<int>* labels,
                                     std::vector<RegionState>* regions) {
  if (!(c.noise_sigma > 0.0)) return 0;
  return MergeBestPairs(
      c, labels, regions,
      [&](const RegionArc& arc) {
        const SurfaceType type_a = (*regions)[arc.a].type;
        const SurfaceType type_b = (*regions)[arc.b].type;
        // A quadric piece next to an analytic one may be part of its
        // surface (ALGORITHMS.md S1 step 3.2 keeps arcs to quadrics); pairs of quadrics are
        // left to the refit merge.
        const bool a_ok = IsAnalytic(type_a) || type_a == SurfaceType::kQuadric;
        const bool b_ok = IsAnalytic(type_b) || type_b == SurfaceType::kQuadric;
        return arc.smooth && a_ok && b_ok && (IsAnalytic(type_a) || IsAnalytic(type_b));
      },
      [&](int a, int b) -> std::optional<PairMerge> {
        const std::optional<UnionTest> t = TestUnion(c, *labels, a, b, *regions);
        if (!t) return std::nullopt;
        return PairMerge{.score = t->gain, .type = t->type, .surface = std::nullopt};
      });
}

}  // namespace meshseg::segment_internal
