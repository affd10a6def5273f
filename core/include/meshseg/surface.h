// File: surface.h
// -----------------------------------------------------------------------------
// The analytic surfaces meshseg reports, as plain data: plane, cylinder, cone,
// sphere, torus and the general quadric of seed 000 eq. (7). Shared vocabulary
// of the `fit` stage (which fits them and measures distances to them), the
// CT-like part generator (its ground truth) and the result contract.
// Directions are unit vectors; angles in radians; lengths in model units.
#ifndef MESHSEG_SURFACE_H_
#define MESHSEG_SURFACE_H_

#include <array>
#include <optional>
#include <variant>

#include <Eigen/Core>

namespace meshseg {

enum class SurfaceType { kPlane, kCylinder, kCone, kSphere, kTorus, kQuadric, kFreeform };

// "plane", "cylinder", "cone", "sphere", "torus", "quadric", "freeform".
const char* SurfaceTypeName(SurfaceType type);

struct Plane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

struct Cylinder {
  Eigen::Vector3d axis_origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_direction = Eigen::Vector3d::UnitZ();
  double radius = 1.0;
};

// Points x with angle(x - apex, axis_direction) = half_angle, on the side the
// axis points to (apex -> opening).
struct Cone {
  Eigen::Vector3d apex = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_direction = Eigen::Vector3d::UnitZ();
  double half_angle = 0.5;  // radians, in (0, pi/2)
};

struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 1.0;
};

struct Torus {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_direction = Eigen::Vector3d::UnitZ();
  double major_radius = 2.0;  // centre to tube centre
  double minor_radius = 0.5;  // tube radius
};

// f(x,y,z) = c0 x² + c1 y² + c2 z² + c3 xy + c4 yz + c5 zx + c6 x + c7 y + c8 z + c9 = 0,
// seed 000 eq. (7).
struct Quadric {
  std::array<double, 10> c{};
};

using Surface = std::variant<Plane, Cylinder, Cone, Sphere, Torus, Quadric>;

// The SurfaceType of the alternative `surface` holds.
SurfaceType TypeOf(const Surface& surface);

// A surface's axis of revolution: a point on it and its unit direction.
struct AxisLine {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

// The axis of a cylinder (through axis_origin), cone (through the apex) or
// torus (through the center); nullopt for the other surfaces.
std::optional<AxisLine> AxisOf(const Surface& surface);

}  // namespace meshseg

#endif  // MESHSEG_SURFACE_H_
