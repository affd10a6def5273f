#include "segment/decide_type.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include <tbb/parallel_for.h>

namespace meshseg::segment_internal {
namespace {

// A cone (one more parameter) replaces a passing cylinder only if it is
// clearly more accurate.
constexpr double kConeGain = 0.8;
// Where n'_i is bent (see DecideCurvedType), a later type wins on test (5)
// alone: if it meets (6) at this share, and its model error is under
// kConeGain of the other's, which must exceed kMinModelError noise sigmas.
constexpr double kBentNormalFraction = 0.75;
// Types within this fraction of the best count as equally good; the earlier
// one in the order of ALGORITHMS.md S1 step 2.5 (cylinder, sphere, cone,
// then our torus) wins.
constexpr double kFractionTie = 0.02;
constexpr double kTorusFractionTie = 0.05;

// True if `surface` meets test (5) at more than alpha of `vertices`.
bool NearAtAlpha(const SegmentContext& c, const Surface& surface, std::span<const int> vertices,
                 const Tolerance& tol) {
  const std::vector<int> sample = Sample(vertices);
  std::size_t near = 0;
  for (const int v : sample) {
    if (std::abs(ProjectVertex(c, surface, v).distance) < tol.distance) ++near;
  }
  return !sample.empty() && near > c.alpha * sample.size();
}

// True if `t` fits `vertices` clearly better than the passing `pass` by
// distance alone: see kBentNormalFraction.
bool WinsOnDistance(const SegmentContext& c, const TypedFit& t, const TypedFit& pass,
                    std::span<const int> vertices, const Tolerance& tol) {
  const double pass_error = ModelError(c, pass.fit);
  return t.fraction >= kBentNormalFraction && !(t.fraction > c.alpha) &&
         pass_error > kMinModelError * c.noise_sigma &&
         ModelError(c, t.fit) < kConeGain * pass_error &&
         NearAtAlpha(c, t.fit.surface, vertices, tol);
}

// The smallest principal radius of curvature of a curved fit near `at`.
double SmallestRadius(const Surface& surface, const Eigen::Vector3d& at) {
  if (const auto* c = std::get_if<Cylinder>(&surface)) return c->radius;
  if (const auto* s = std::get_if<Sphere>(&surface)) return s->radius;
  if (const auto* t = std::get_if<Torus>(&surface)) {
    // The tube's radius, or the radius around the axis, rho / cos(theta) at
    // the tube angle theta of the point nearest `at`: R - r at the inner
    // equator of a torus fitted to a cylinder band (noise can turn a
    // cylinder band's fit into a torus with R and r some 200 times the
    // cylinder's radius and R - r equal to it).
    const Eigen::Vector3d d = at - t->center;
    const double along = d.dot(t->axis_direction);
    const Eigen::Vector2d from_tube((d - along * t->axis_direction).norm() - t->major_radius,
                                    along);
    if (!(from_tube.norm() > 0.0)) return t->minor_radius;
    const double cos_theta = from_tube.x() / from_tube.norm();
    const double rho = t->major_radius + t->minor_radius * cos_theta;
    return std::min(t->minor_radius, std::abs(rho) / std::max(std::abs(cos_theta), 1e-9));
  }
  if (const auto* k = std::get_if<Cone>(&surface)) {
    const Eigen::Vector3d d = at - k->apex;
    const double rho = (d - d.dot(k->axis_direction) * k->axis_direction).norm();
    return rho / std::max(std::cos(k->half_angle), 1e-9);
  }
  return 0.0;  // quadric: not judged here
}

// See NearlyFlat in decide_type.h.
bool NearlyFlatImpl(const SegmentContext& c, const Surface& surface, double rms,
                    std::span<const int> vertices, const Tolerance& tol) {
  if (vertices.empty()) return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const int v : vertices) centroid += c.position(v);
  centroid /= static_cast<double>(vertices.size());
  // A cylinder or cone is straight along its rulings; it bends only across
  // them (a noisy plane strip 60 long and 10 high can grow as a cylinder of
  // radius ~570 with its axis along the strip: bent only across its 10, by
  // a sagitta of 0.02).
  Eigen::Vector3d straight = Eigen::Vector3d::Zero();
  if (const auto* cylinder = std::get_if<Cylinder>(&surface)) straight = cylinder->axis_direction;
  if (const auto* cone = std::get_if<Cone>(&surface)) {
    const Eigen::Vector3d ruling = centroid - cone->apex;
    if (ruling.norm() > 0.0) straight = ruling / ruling.norm();
  }
  double extent2 = 0.0;
  for (const int v : vertices) {
    const Eigen::Vector3d d = c.position(v) - centroid;
    extent2 = std::max(extent2, (d - d.dot(straight) * straight).squaredNorm());
  }
  const double radius = SmallestRadius(surface, centroid);
  if (!(radius > 0.0)) return false;
  const double max_turn = std::acos(std::clamp(tol.cos_angle, -1.0, 1.0));
  const double sagitta = extent2 / (2.0 * radius);
  return sagitta < std::max(tol.distance, 2.0 * rms) &&
         std::sqrt(extent2) / radius < max_turn;
}

}  // namespace

TypedFit TryType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices,
                 const Tolerance& tol) {
  TypedFit k;
  k.type = type;
  k.fit = FitType(c, type, vertices);
  if (k.fit.ok()) k.fraction = FitFraction(c, k.fit.surface, vertices, tol);
  return k;
}

double ModelErrorOfMeanSquare(const SegmentContext& c, double mean_square) {
  return std::sqrt(std::max(0.0, mean_square - c.noise_sigma * c.noise_sigma));
}

double ModelError(const SegmentContext& c, const FitResult& fit) {
  return ModelErrorOfMeanSquare(c, fit.rms_distance * fit.rms_distance);
}

bool FitsAtNoise(const SegmentContext& c, const FitResult& fit) {
  return fit.ok() && ModelError(c, fit) <= kMinModelError * c.noise_sigma;
}

bool FitsNearNoise(const SegmentContext& c, const FitResult& fit) {
  return fit.ok() && ModelError(c, fit) <= kScoredNearError * c.noise_sigma;
}

int ParameterCount(SurfaceType type) {
  switch (type) {
    case SurfaceType::kPlane: return 3;     // unit normal 2, offset
    case SurfaceType::kSphere: return 4;    // centre 3, radius
    case SurfaceType::kCylinder: return 5;  // axis line 4, radius
    case SurfaceType::kCone: return 6;      // apex 3, axis 2, half-angle
    case SurfaceType::kTorus: return 7;     // centre 3, axis 2, two radii
    case SurfaceType::kQuadric: return 9;   // 10 coefficients up to scale
    case SurfaceType::kFreeform: return 0;
  }
  return 0;
}

bool IsLimitOf(SurfaceType special, SurfaceType general) {
  if (general == SurfaceType::kTorus) {
    return special == SurfaceType::kCone || special == SurfaceType::kCylinder;
  }
  return general == SurfaceType::kCone && special == SurfaceType::kCylinder;
}

double InformationScore(const SegmentContext& c, double mean_square, std::size_t count,
                        int parameters) {
  const double m = static_cast<double>(std::min(count, kMaxSample));
  const double floor = kMinModelError * c.noise_sigma;
  return m * std::log(std::max({mean_square, floor * floor, std::numeric_limits<double>::min()})) +
         parameters * std::log(m);
}

bool TakesOverNearTheNoise(const SegmentContext& c, SurfaceType type, double model_error,
                           double score, SurfaceType own, double own_score) {
  if (!(model_error <= kScoredNearError * c.noise_sigma)) return false;
  return IsLimitOf(type, own) ? score < own_score + kScoreMargin : score + kScoreMargin < own_score;
}

ScoredFit ScoreType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices) {
  ScoredFit out{.type = type, .fit = FitType(c, type, vertices)};
  if (out.fit.ok()) {
    out.score = InformationScore(c, out.fit.rms_distance * out.fit.rms_distance, vertices.size(),
                                 ParameterCount(type));
  }
  return out;
}

ScoredFit BestScoredType(const SegmentContext& c, std::span<const int> vertices) {
  ScoredFit best = ScoreType(c, SurfaceType::kPlane, vertices);
  for (ScoredFit& s : ScoreCurvedTypes(c, vertices)) {
    if (s.score < best.score) best = std::move(s);
  }
  return best;
}

std::optional<ScoredFit> TypeThatFitsInstead(const SegmentContext& c, const RegionState& r) {
  ScoredFit best = BestScoredType(c, r.vertices);
  if (!best.fit.ok()) return std::nullopt;
  const double n = static_cast<double>(r.vertices.size());
  const double own = InformationScore(c, SquaredDistances(c, r.surface, r.vertices) / n,
                                      r.vertices.size(), ParameterCount(r.type));
  if (!(best.score + kScoreMargin < own)) return std::nullopt;
  return best;
}

std::array<ScoredFit, kCurvedTypes.size()> ScoreCurvedTypes(const SegmentContext& c,
                                                            std::span<const int> vertices) {
  // The fits read only c and the vertices: concurrent, each into its slot.
  std::array<ScoredFit, kCurvedTypes.size()> out;
  tbb::parallel_for(std::size_t{0}, kCurvedTypes.size(),
                    [&](std::size_t t) { out[t] = ScoreType(c, kCurvedTypes[t], vertices); });
  return out;
}

bool NearlyFlat(const SegmentContext& c, const Surface& surface, double rms,
                std::span<const int> vertices, const Tolerance& tol) {
  return NearlyFlatImpl(c, surface, rms, vertices, tol);
}

std::optional<TypedFit> PlaneIfFits(const SegmentContext& c, std::span<const int> vertices,
                                    const Tolerance& tol) {
  TypedFit plane = TryType(c, SurfaceType::kPlane, vertices, tol);
  if (plane.fraction > c.alpha) return plane;
  return std::nullopt;
}

TypedFit DecideCurvedType(const SegmentContext& c, std::span<const int> vertices,
                          const Tolerance& tol) {
  std::array<TypedFit, kCurvedTypes.size()> k;  // concurrent fits, each into its slot
  tbb::parallel_for(std::size_t{0}, kCurvedTypes.size(),
                    [&](std::size_t t) { k[t] = TryType(c, kCurvedTypes[t], vertices, tol); });
  // Of cylinder and cone, the more accurate (ALGORITHMS.md S1 step 2.5).
  if (k[2].fraction >= k[0].fraction - kFractionTie &&
      k[2].fit.rms_distance < kConeGain * k[0].fit.rms_distance) {
    k[0].fraction = 0.0;
  } else if (k[0].fraction >= k[2].fraction - kFractionTie) {
    k[2].fraction = 0.0;
  }
  // The torus (two more parameters than a cone) replaces the best simpler
  // type only if it is clearly more accurate; fractions within
  // kTorusFractionTie count as equal and the simpler type wins. So does a
  // simpler type that meets (5) at alpha with a model error at the noise:
  // the torus then gains fraction only by bending with n'_i where it is
  // bent (a narrow countersink band at sigma = 0.15 h: cone 0.71, torus
  // 0.76, both at rms = sigma).
  const TypedFit* simple = &k[0];
  for (int t = 1; t < 3; ++t) {
    if (k[t].fraction > simple->fraction) simple = &k[t];
  }
  const bool simple_at_noise = simple->fraction > 0.0 &&
                               ModelError(c, simple->fit) <= kMinModelError * c.noise_sigma &&
                               NearAtAlpha(c, simple->fit.surface, vertices, tol);
  if (simple->fraction > 0.0 &&
      (k[3].fraction < simple->fraction + kTorusFractionTie || simple_at_noise) &&
      !(k[3].fit.rms_distance < kConeGain * simple->fit.rms_distance)) {
    k[3].fraction = 0.0;
  }
  // The first type in S1's order that passes the alpha test, unless
  // a later passing one is clearly more accurate at no loss of fraction (a
  // sphere passes on a noisy cone band only thanks to the tolerances), or
  // a later one wins on distance where n'_i is bent: on a band narrower
  // than N'(i, W2) between two creases the sharp test misses (a 45-degree
  // chamfer, 6 h wide), n'_i turns toward both neighbours as a sphere's
  // normals would, and at sigma = 0.15 h a fifth of the n_i miss th_nm by
  // noise.
  // The later type then keeps the fraction the earlier one earned ...
  TypedFit* pass = nullptr;
  for (TypedFit& t : k) {
    if (pass == nullptr) {
      if (t.fraction > c.alpha) pass = &t;
    } else if (t.fraction > c.alpha && t.fraction >= pass->fraction - kFractionTie &&
               t.fit.rms_distance < kConeGain * pass->fit.rms_distance) {
      pass = &t;
    } else if (WinsOnDistance(c, t, *pass, vertices, tol)) {
      t.fraction = pass->fraction;
      pass = &t;
    }
  }
  if (pass != nullptr &&
      NearlyFlat(c, pass->fit.surface, pass->fit.rms_distance, vertices, tol)) {
    // Within the tolerances the plane is the same surface; it keeps the
    // fitting fraction the curved type earned for the alpha test.
    TypedFit plane = TryType(c, SurfaceType::kPlane, vertices, tol);
    if (plane.fit.ok()) {
      plane.fraction = std::max(plane.fraction, pass->fraction);
      return plane;
    }
  }
  if (pass != nullptr) return *pass;
  // ... else the best, for the caller's trimming.
  double best = 0.0;
  for (const TypedFit& t : k) best = std::max(best, t.fraction);
  for (const TypedFit& t : k) {
    if (t.fraction > 0.0 && t.fraction >= best - kFractionTie) return t;
  }
  TypedFit quadric = TryType(c, SurfaceType::kQuadric, vertices, tol);
  return quadric;
}

}  // namespace meshseg::segment_internal
