#include "brep/occt_surface.h"

#include <cmath>
#include <type_traits>
#include <variant>

#include <Eigen/Geometry>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>

#include "brep/bspline_surface_fit.h"
#include "brep/surface_query.h"
#include "meshseg/fit.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

// A radial direction counts as the region's bulk direction when the mean of
// the unit radial directions is at least this long (a full turn averages ~0).
constexpr double kMinBulk = 0.05;

gp_Dir ToDir(const Vector3d& d) { return gp_Dir(d.x(), d.y(), d.z()); }

Vector3d Centroid(const std::vector<Vector3d>& points) {
  Vector3d c = Vector3d::Zero();
  for (const Vector3d& p : points) c += p;
  return points.empty() ? c : Vector3d(c / static_cast<double>(points.size()));
}

// The seam direction of a surface that goes all the way round the axis `d`:
// the world axis most nearly perpendicular to it, made perpendicular. It
// varies continuously with the axis, so coaxial surfaces fitted apart (a
// shaft's steps) share their seam, and the vertices of the circles between
// them (boundary_edges.cc) sit on it.
Vector3d SeamDirection(const Vector3d& d) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(d[i]) < std::abs(d[k])) k = i;
  }
  const Vector3d e = Vector3d::Unit(k);
  return (e - e.dot(d) * d).normalized();
}

// The frame of a surface turning about the axis (origin, axis): the x
// direction (parameter u = 0, the seam of a periodic surface) points away
// from the mean radial direction of the region's points, so a region that
// does not go all the way round is not cut by the seam.
gp_Ax3 AxialFrame(const Vector3d& origin, const Vector3d& axis,
                  const std::vector<Vector3d>& points) {
  const Vector3d d = axis.normalized();
  Vector3d bulk = Vector3d::Zero();
  for (const Vector3d& p : points) {
    const Vector3d v = p - origin;
    const Vector3d radial = v - v.dot(d) * d;
    if (radial.norm() > 0.0) bulk += radial.normalized();
  }
  if (!points.empty()) bulk /= static_cast<double>(points.size());
  Vector3d x = bulk.norm() >= kMinBulk ? Vector3d(-bulk.normalized()) : SeamDirection(d);
  x = (x - x.dot(d) * d).normalized();
  return gp_Ax3(ToPnt(origin), ToDir(d), ToDir(x));
}

// Points of the axis nearest the region's centroid.
Vector3d AxisPointNearest(const Vector3d& origin, const Vector3d& axis, const Vector3d& p) {
  const Vector3d d = axis.normalized();
  return origin + (p - origin).dot(d) * d;
}

Handle(Geom_Surface) AnalyticSurface(const Surface& surface, const std::vector<Vector3d>& points) {
  const Vector3d centroid = Centroid(points);
  return std::visit(
      [&](const auto& s) -> Handle(Geom_Surface) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          const Vector3d n = s.normal.normalized();
          const Vector3d origin = centroid - (centroid - s.point).dot(n) * n;
          return new Geom_Plane(gp_Ax3(ToPnt(origin), ToDir(n), ToDir(n.unitOrthogonal())));
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          if (!(s.radius > 0.0)) return nullptr;
          const Vector3d origin = AxisPointNearest(s.axis_origin, s.axis_direction, centroid);
          return new Geom_CylindricalSurface(AxialFrame(origin, s.axis_direction, points),
                                             s.radius);
        } else if constexpr (std::is_same_v<T, Cone>) {
          // Framed at the region's mean height above the apex, where the
          // reference circle has a positive radius.
          const Vector3d d = s.axis_direction.normalized();
          const double height = (centroid - s.apex).dot(d);
          if (!(height > 0.0) || !(s.half_angle > 0.0 && s.half_angle < M_PI / 2)) return nullptr;
          return new Geom_ConicalSurface(AxialFrame(s.apex + height * d, d, points), s.half_angle,
                                         height * std::tan(s.half_angle));
        } else if constexpr (std::is_same_v<T, Sphere>) {
          if (!(s.radius > 0.0)) return nullptr;
          // The poles lie on the frame's axis: put it across the region's
          // mean direction, and the seam opposite to it.
          Vector3d bulk = Vector3d::Zero();
          for (const Vector3d& p : points) bulk += (p - s.center).normalized();
          if (!points.empty()) bulk /= static_cast<double>(points.size());
          const Vector3d x = bulk.norm() >= kMinBulk ? Vector3d(-bulk.normalized())
                                                     : Vector3d::UnitX();
          const Vector3d z = x.unitOrthogonal();
          return new Geom_SphericalSurface(gp_Ax3(ToPnt(s.center), ToDir(z), ToDir(x)), s.radius);
        } else if constexpr (std::is_same_v<T, Torus>) {
          if (!(s.minor_radius > 0.0 && s.major_radius > s.minor_radius)) return nullptr;
          return new Geom_ToroidalSurface(AxialFrame(s.center, s.axis_direction, points),
                                          s.major_radius, s.minor_radius);
        } else {
          return nullptr;
        }
      },
      surface);
}

// +1 if the surface normal agrees with the mesh's outward face normals on
// most of the sampled faces, -1 if it disagrees, 0 if none projects.
int OutwardSign(const Handle(Geom_Surface) & surface, const RegionSamples& samples) {
  double vote = 0.0;
  for (size_t i = 0; i < samples.face_centroids.size(); ++i) {
    const std::optional<SurfacePoint> q = ClosestPoint(surface, samples.face_centroids[i]);
    if (q) vote += q->normal.dot(samples.face_normals[i]);
  }
  return vote > 0.0 ? 1 : (vote < 0.0 ? -1 : 0);
}

}  // namespace

RegionSurface MakeRegionSurface(const Region& region, const RegionSamples& samples, double l_avg,
                                double noise_sigma) {
  RegionSurface out;
  const SurfaceType type = region.type;
  if (type == SurfaceType::kQuadric || type == SurfaceType::kFreeform) {
    BsplineSurfaceFit fit = FitBsplineSurface(region, samples, l_avg, noise_sigma);
    if (fit.surface.IsNull()) {
      out.failure = fit.failure;
      return out;
    }
    out.surface = fit.surface;
    out.fitted = true;
  } else {
    out.surface = AnalyticSurface(region.surface, samples.points);
    if (out.surface.IsNull()) {
      out.failure = std::string("degenerate ") + SurfaceTypeName(type) + " parameters";
      return out;
    }
  }
  out.sign = OutwardSign(out.surface, samples);
  if (out.sign == 0) {
    out.surface.Nullify();
    out.failure = "no face of the region projects onto its surface";
  }
  return out;
}

}  // namespace meshseg::brep_internal
