#include "brep/surface_query.h"

#include <cmath>

#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Precision.hxx>

namespace meshseg::brep_internal {

std::optional<SurfacePoint> ClosestPoint(const Handle(Geom_Surface) & surface,
                                         const Eigen::Vector3d& p) {
  GeomAPI_ProjectPointOnSurf projection(ToPnt(p), surface);
  if (!projection.IsDone() || projection.NbPoints() == 0) return std::nullopt;
  SurfacePoint out;
  projection.LowerDistanceParameters(out.u, out.v);
  GeomLProp_SLProps props(surface, out.u, out.v, 1, 1e-9);
  if (!props.IsNormalDefined()) return std::nullopt;
  out.point = ToEigen(props.Value());
  out.normal = ToEigen(gp_Vec(props.Normal()));
  out.distance = (p - out.point).dot(out.normal);
  return out;
}

double ClosestParameter(const Handle(Geom_Curve) & curve, const Eigen::Vector3d& p,
                                       double first, double last) {
  // The projection returns extrema only; the (finite) ends of the range
  // compete.
  const gp_Pnt q = ToPnt(p);
  double best_t = Precision::IsInfinite(first) ? 0.0 : first;
  double best = Precision::IsInfinite(first) ? INFINITY : q.Distance(curve->Value(first));
  if (!Precision::IsInfinite(last)) {
    if (const double d = q.Distance(curve->Value(last)); d < best) {
      best = d;
      best_t = last;
    }
  }
  GeomAPI_ProjectPointOnCurve projection(q, curve, first, last);
  if (projection.NbPoints() > 0 && projection.LowerDistance() < best) {
    best_t = projection.LowerDistanceParameter();
  }
  return best_t;
}

}  // namespace meshseg::brep_internal
