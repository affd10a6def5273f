// Closest points on OpenCASCADE surfaces and curves, in Eigen terms.
#ifndef MESHSEG_SRC_BREP_SURFACE_QUERY_H_
#define MESHSEG_SRC_BREP_SURFACE_QUERY_H_

#include <optional>

#include <Eigen/Core>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace meshseg::brep_internal {

inline gp_Pnt ToPnt(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }
inline Eigen::Vector3d ToEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Eigen::Vector3d ToEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

struct SurfacePoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // D1U x D1V, unit
  double u = 0.0;
  double v = 0.0;
  double distance = 0.0;  // signed, positive on the side the normal points to
};

// Returns the point of `surface` closest to `p`, or nullopt where the
// projection fails or the normal is undefined (an apex or pole).
std::optional<SurfacePoint> ClosestPoint(const Handle(Geom_Surface) & surface,
                                         const Eigen::Vector3d& p);

// Returns the parameter of the point of `curve` closest to `p` within
// [first, last] (finite).
double ClosestParameter(const Handle(Geom_Curve) & curve, const Eigen::Vector3d& p,
                                       double first, double last);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_SURFACE_QUERY_H_
