#include "brep/edge_curve.h"

#include <algorithm>

#include <GeomAPI_IntSS.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Precision.hxx>
#include <gp_Ax2.hxx>

#include "brep/fitted_curve.h"
#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

// A fitted curve replaces the closed-form line or circle of a tangent
// contact when its gap is below this share of the closed form's.
constexpr double kSimplerShare = 0.5;

gp_Dir ToDir(const Eigen::Vector3d& d) {
  const Eigen::Vector3d n = d.normalized();
  return gp_Dir(n.x(), n.y(), n.z());
}

// The topology stage's closed-form line or circle as an OCCT curve.
Handle(Geom_Curve) HintCurve(const CurveGeometry& hint) {
  if (!hint.analytic || hint.direction.norm() == 0.0) return nullptr;
  if (hint.type == CurveGeometryType::kLine) {
    return new Geom_Line(ToPnt(hint.point), ToDir(hint.direction));
  }
  if (hint.type == CurveGeometryType::kCircle && hint.radius > 0.0) {
    return new Geom_Circle(gp_Ax2(ToPnt(hint.point), ToDir(hint.direction)), hint.radius);
  }
  return nullptr;
}

}  // namespace

const std::vector<Handle(Geom_Curve)>& IntersectionCache::Branches(
    int a, int b, std::span<const Handle(Geom_Surface)> surfaces) {
  const std::pair<int, int> key = std::minmax(a, b);
  auto [it, inserted] = branches_.try_emplace(key);
  if (!inserted) return it->second;
  GeomAPI_IntSS intersection(surfaces[key.first], surfaces[key.second], Precision::Confusion());
  if (intersection.IsDone()) {
    for (int i = 1; i <= intersection.NbLines(); ++i) it->second.push_back(intersection.Line(i));
  }
  return it->second;
}

std::optional<EdgeCurve> ChooseEdgeCurve(const EdgeRequest& request,
                                         std::span<const Handle(Geom_Surface)> surfaces,
                                         IntersectionCache* cache) {
  const Handle(Geom_Surface) pair[2] = {
      surfaces[request.left], request.right >= 0 ? surfaces[request.right] : nullptr};
  std::optional<EdgeCurve> best;
  // A candidate that follows the boundary; exact if it lies on both surfaces.
  auto consider = [&](const Handle(Geom_Curve) & curve, bool must_be_exact) {
    std::optional<TrimmedCurve> t =
        TrimAlong(curve, request.polyline, request.start, request.end);
    if (!t || t->deviation > request.tolerance) return;
    MeasureGap(pair, &*t);
    const bool exact = t->gap <= request.exact_gap;
    if (must_be_exact && !exact) return;
    if (!best || (exact && !best->exact) ||
        (exact == best->exact && t->deviation < best->trimmed.deviation)) {
      best = EdgeCurve{*t, exact};
    }
  };
  if (!pair[1].IsNull()) {
    if (request.transversal) {
      for (const Handle(Geom_Curve) & branch :
           cache->Branches(request.left, request.right, surfaces)) {
        consider(branch, true);
      }
    }
    if (best) return best;
    // A tangent contact (fillet) has no transversal intersection; the
    // closed-form line or circle of contact stands in, with its gap.
    if (const Handle(Geom_Curve) hint = HintCurve(request.hint); !hint.IsNull()) {
      consider(hint, false);
    }
    // A closed form within the noise of both surfaces is as close as a
    // fitted curve can be shown to be: no fit.
    if (best && best->trimmed.gap <= request.surface_offset) return best;
  }
  std::optional<TrimmedCurve> fitted =
      FitEdgeCurve(request.polyline, pair[0], pair[1], request.start, request.end, request.hint,
                   request.tolerance, request.l_avg);
  if (fitted) MeasureGap(pair, &*fitted);
  // The closed form is the simpler curve; the fitted one wins where it lies
  // clearly closer to both surfaces (they cross where the closed form
  // assumed they touch).
  if (fitted && (!best || (fitted->deviation <= request.tolerance &&
                           fitted->gap < kSimplerShare * best->trimmed.gap))) {
    return EdgeCurve{*fitted, fitted->gap <= request.exact_gap};
  }
  return best;
}

}  // namespace meshseg::brep_internal
