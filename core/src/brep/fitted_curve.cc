#include "brep/fitted_curve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <GCPnts_AbscissaPoint.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Circle.hxx>
#include <Precision.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <gp_Ax2.hxx>

#include "brep/corner_points.h"
#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

constexpr int kMinPoints = 8;
constexpr int kMaxPoints = 200;
constexpr int kSmoothPasses = 2;
// A line or arc is taken when the drawn points stay within this fraction of
// the tolerance of it; the B-spline approximates them within kSplineShare of
// l_avg: the drawn points lie on both surfaces where those cross, and the
// spline should too.
constexpr double kFitShare = 0.25;
constexpr double kSplineShare = 1e-3;

// Moves `p` to the nearest point where the surfaces meet (between them
// where they only touch), or onto `left` alone at the border.
Vector3d DrawOnto(const Vector3d& p, const Handle(Geom_Surface) & left,
                  const Handle(Geom_Surface) & right, double max_move) {
  if (right.IsNull()) {
    const std::optional<SurfacePoint> a = ClosestPoint(left, p);
    return a ? a->point : p;
  }
  const Handle(Geom_Surface) both[2] = {left, right};
  return CornerPoint(p, both, max_move);
}

// True if every point lies within `tolerance` of both surfaces (they cross
// there), so a spline through them may follow them closely.
bool OnBoth(const std::vector<Vector3d>& points, const Handle(Geom_Surface) & left,
            const Handle(Geom_Surface) & right, double tolerance) {
  for (const Vector3d& p : points) {
    for (const Handle(Geom_Surface) & s : {left, right}) {
      if (s.IsNull()) continue;
      const std::optional<SurfacePoint> q = ClosestPoint(s, p);
      if (!q || std::abs(q->distance) > tolerance) return false;
    }
  }
  return true;
}

double MaxDistance(const Handle(Geom_Curve) & c, double first, double last,
                   const std::vector<Vector3d>& points) {
  std::vector<Vector3d> q;
  constexpr int kSamples = 64;
  for (int j = 0; j < kSamples; ++j) {
    q.push_back(ToEigen(c->Value(first + (last - first) * j / (kSamples - 1))));
  }
  double d = 0.0;
  for (const Vector3d& p : points) d = std::max(d, DistanceToPolyline(p, q));
  return d;
}

double ArcLength(const TrimmedCurve& t) {
  return GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(t.curve), std::min(t.first, t.last),
                                      std::max(t.first, t.last));
}

// A spline through `pts` (periodic when `closed`: the last repeats the
// first) within `fit_tolerance`, trimmed along `polyline`.
std::optional<TrimmedCurve> Spline(const std::vector<Vector3d>& pts, bool closed,
                                   double fit_tolerance, std::span<const Vector3d> polyline,
                                   const std::optional<Vector3d>& start,
                                   const std::optional<Vector3d>& end) {
  if (closed) {
    Handle(TColgp_HArray1OfPnt) array =
        new TColgp_HArray1OfPnt(1, static_cast<int>(pts.size()) - 1);
    for (size_t i = 0; i + 1 < pts.size(); ++i)
      array->SetValue(static_cast<int>(i) + 1, ToPnt(pts[i]));
    GeomAPI_Interpolate interpolate(array, Standard_True, Precision::Confusion());
    interpolate.Perform();
    if (!interpolate.IsDone()) return std::nullopt;
    return TrimAlong(interpolate.Curve(), polyline, start, end);
  }
  TColgp_Array1OfPnt array(1, static_cast<int>(pts.size()));
  for (size_t i = 0; i < pts.size(); ++i) array(static_cast<int>(i) + 1) = ToPnt(pts[i]);
  GeomAPI_PointsToBSpline approx(array, 3, 8, GeomAbs_C2, fit_tolerance);
  if (!approx.IsDone()) return std::nullopt;
  return TrimAlong(approx.Curve(), polyline, start, end);
}

}  // namespace

std::optional<TrimmedCurve> FitEdgeCurve(
    std::span<const Vector3d> polyline, const Handle(Geom_Surface) & left,
    const Handle(Geom_Surface) & right, const std::optional<Vector3d>& start,
    const std::optional<Vector3d>& end, const CurveGeometry& hint, double tolerance, double l_avg) {
  double length = 0.0;
  for (size_t i = 1; i < polyline.size(); ++i) length += (polyline[i] - polyline[i - 1]).norm();
  if (polyline.size() < 2 || !(length > 0.0)) return std::nullopt;
  const int count =
      std::clamp(static_cast<int>(length / std::max(l_avg, 1e-300)), kMinPoints, kMaxPoints);
  std::vector<Vector3d> pts = Resample(polyline, count);
  // Closed: no vertex, or both ends on one vertex.
  const bool closed = !start || (*end - *start).norm() <= 1e-6 * length;
  if (start) {
    pts.front() = *start;
    pts.back() = *end;
  }
  // Laplacian passes take out the staircase of mesh edges, then the points
  // go onto the surfaces. The ends of an open curve stay on its vertices.
  for (int pass = 0; pass < kSmoothPasses; ++pass) {
    std::vector<Vector3d> next = pts;
    for (size_t i = 1; i + 1 < pts.size(); ++i)
      next[i] = 0.5 * pts[i] + 0.25 * (pts[i - 1] + pts[i + 1]);
    pts = std::move(next);
  }
  std::vector<Vector3d> smoothed = pts;
  if (closed) smoothed.back() = smoothed.front();
  const size_t fixed = start ? 1 : 0;
  for (size_t i = fixed; i + fixed < pts.size(); ++i) {
    pts[i] = DrawOnto(pts[i], left, right, tolerance);
  }
  if (closed) pts.back() = pts.front();
  // Points on both surfaces (they cross) are fitted closely; points between
  // tangent surfaces carry the boundary's noise along the contact and are
  // fitted within a share of the tolerance.
  const double fit_tolerance =
      OnBoth(pts, left, right, kSplineShare * l_avg) ? kSplineShare * l_avg : kFitShare * tolerance;

  std::vector<Handle(Geom_Curve)> candidates;
  if (!closed && (*end - *start).norm() > 0.0) {
    GC_MakeSegment segment(ToPnt(*start), ToPnt(*end));
    if (segment.IsDone()) candidates.push_back(segment.Value());
    GC_MakeArcOfCircle arc(ToPnt(*start), ToPnt(pts[pts.size() / 2]), ToPnt(*end));
    if (arc.IsDone()) candidates.push_back(arc.Value());
  }
  if (closed && hint.type == CurveGeometryType::kCircle && hint.radius > 0.0) {
    const Vector3d n = hint.direction.normalized();
    candidates.push_back(
        new Geom_Circle(gp_Ax2(ToPnt(hint.point), gp_Dir(n.x(), n.y(), n.z())), hint.radius));
  }
  for (const Handle(Geom_Curve) & c : candidates) {
    const double first = c->FirstParameter();
    const double last = c->IsPeriodic() ? first + c->Period() : c->LastParameter();
    if (MaxDistance(c, first, last, pts) > fit_tolerance) continue;
    if (std::optional<TrimmedCurve> t = TrimAlong(c, polyline, start, end)) return t;
  }
  // A curve runs along its boundary, which the mesh's staircase only
  // lengthens: a spline longer than the boundary by more than the tolerance
  // at each end doubles back on itself (drawn points out of order along an
  // intersection stay within the Hausdorff bound but zig-zag along it). The
  // smoothed points before drawing are in the boundary's order; they are
  // the fallback.
  auto runs_along = [&](const std::optional<TrimmedCurve>& t) {
    return t && ArcLength(*t) <= length + 2.0 * tolerance;
  };
  std::optional<TrimmedCurve> t = Spline(pts, closed, fit_tolerance, polyline, start, end);
  if (runs_along(t)) return t;
  t = Spline(smoothed, closed, kFitShare * tolerance, polyline, start, end);
  return runs_along(t) ? t : std::nullopt;
}

}  // namespace meshseg::brep_internal
