#include "segment/decide_type.h"

#include <algorithm>
#include <array>

namespace meshseg::segment_internal {
namespace {

// A cone (one more parameter) replaces a passing cylinder only if it is
// clearly more accurate.
constexpr double kConeGain = 0.8;
// Types within this fraction of the best count as equally good; the earlier
// one in seed 000's order (cylinder, sphere, cone, torus) wins.
constexpr double kFractionTie = 0.02;
constexpr double kTorusFractionTie = 0.05;

TypedFit Try(const SegmentContext& c, SurfaceType type, std::span<const int> vertices,
             const Tolerance& tol) {
  TypedFit k;
  k.type = type;
  k.fit = FitType(c, type, vertices);
  if (k.fit.ok()) k.fraction = FitFraction(c, k.fit.surface, vertices, tol);
  return k;
}

}  // namespace

std::optional<TypedFit> PlaneIfFits(const SegmentContext& c, std::span<const int> vertices,
                                    const Tolerance& tol) {
  TypedFit plane = Try(c, SurfaceType::kPlane, vertices, tol);
  if (plane.fraction > c.alpha) return plane;
  return std::nullopt;
}

TypedFit DecideCurvedType(const SegmentContext& c, std::span<const int> vertices,
                          const Tolerance& tol) {
  std::array<TypedFit, 4> k = {Try(c, SurfaceType::kCylinder, vertices, tol),
                               Try(c, SurfaceType::kSphere, vertices, tol),
                               Try(c, SurfaceType::kCone, vertices, tol),
                               Try(c, SurfaceType::kTorus, vertices, tol)};
  // Of cylinder and cone, the more accurate (seed 000 §3 step 5).
  if (k[2].fraction >= k[0].fraction - kFractionTie &&
      k[2].fit.rms_distance < kConeGain * k[0].fit.rms_distance) {
    k[0].fraction = 0.0;
  } else if (k[0].fraction >= k[2].fraction - kFractionTie) {
    k[2].fraction = 0.0;
  }
  // The torus (two more parameters than a cone) replaces the best simpler
  // type only if it is clearly more accurate; fractions within
  // kTorusFractionTie count as equal and the simpler type wins.
  const TypedFit* simple = &k[0];
  for (int t = 1; t < 3; ++t) {
    if (k[t].fraction > simple->fraction) simple = &k[t];
  }
  if (simple->fraction > 0.0 && k[3].fraction < simple->fraction + kTorusFractionTie &&
      !(k[3].fit.rms_distance < kConeGain * simple->fit.rms_distance)) {
    k[3].fraction = 0.0;
  }
  // The first type in seed 000's order that passes the alpha test, unless
  // a later passing one is clearly more accurate at no loss of fraction (a
  // sphere passes on a noisy cone band only thanks to the tolerances) ...
  const TypedFit* pass = nullptr;
  for (const TypedFit& t : k) {
    if (!(t.fraction > c.alpha)) continue;
    if (pass == nullptr || (t.fraction >= pass->fraction - kFractionTie &&
                            t.fit.rms_distance < kConeGain * pass->fit.rms_distance)) {
      pass = &t;
    }
  }
  if (pass != nullptr) return *pass;
  // ... else the best, for the caller's trimming.
  double best = 0.0;
  for (const TypedFit& t : k) best = std::max(best, t.fraction);
  for (const TypedFit& t : k) {
    if (t.fraction > 0.0 && t.fraction >= best - kFractionTie) return t;
  }
  TypedFit quadric = Try(c, SurfaceType::kQuadric, vertices, tol);
  return quadric;
}

}  // namespace meshseg::segment_internal
