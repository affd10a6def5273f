// File: fit.h
// -----------------------------------------------------------------------------
// The `fit` stage: least-squares fitting of the analytic surfaces of
// surface.h and of the local quadratic height function, and the geometric
// queries region growing needs (closest point, signed distance, normal there).
// Seed 000 §5 (fitting, quadric closest point), seed 002 (fast linear initial
// fits from smoothed normals n'_i), then geometric refinement by
// Levenberg–Marquardt in one shared least-squares loop.
//
// In: points (and, where the method needs them, smoothed normals n'_i).
// Out: FitResult with the surface and its rms / max distance. A region that
// fits no cylinder is an answer (converged = false or large errors), not an
// error; degenerate input (too few / collinear points) yields ok() == false
// and finite numbers, never NaN.
#ifndef MESHSEG_FIT_H_
#define MESHSEG_FIT_H_

#include <array>
#include <span>

#include <Eigen/Core>

#include "meshseg/surface.h"

namespace meshseg {

struct FitParams {
  // Max Levenberg–Marquardt iterations of the geometric refinement.
  int max_iterations = 30;
  // Stop when the relative decrease of the squared error is below this.
  double relative_tolerance = 1e-10;
  // Refine the linear initial fit by geometric distance (seed 000 §5).
  bool refine = true;
};

// Points to fit, with optional per-point normals (smoothed normals n'_i,
// seed 002) and weights (e.g. vertex areas). Empty spans mean "not given".
struct FitInput {
  std::span<const Eigen::Vector3d> points;
  std::span<const Eigen::Vector3d> normals;
  std::span<const double> weights;
};

struct FitResult {
  Surface surface;
  double rms_distance = 0.0;  // root mean square of point-to-surface distance
  double max_distance = 0.0;
  int iterations = 0;         // refinement iterations used
  bool valid = false;         // false: degenerate input, surface meaningless

  bool ok() const { return valid; }
};

// Closest point on a surface to a query point, the unit surface normal there
// and the signed distance (positive on the side the normal points to).
struct Projection {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double distance = 0.0;
};

// Closed form for plane, cylinder, cone, sphere, torus; for the quadric the
// 3-step line/gradient iteration of seed 000 §5 starting along `hint_direction`
// (the vertex normal n_i; zero vector = use the gradient at p).
Projection Project(const Surface& surface, const Eigen::Vector3d& p,
                   const Eigen::Vector3d& hint_direction = Eigen::Vector3d::Zero());

// Signed distance from p to the surface (|.| of Project's distance for the
// closed forms; the algebraic-to-geometric estimate |f| / |grad f| refined by
// the 3-step projection for the quadric).
double SignedDistance(const Surface& surface, const Eigen::Vector3d& p);

FitResult FitPlane(const FitInput& input, const FitParams& params = {});
FitResult FitSphere(const FitInput& input, const FitParams& params = {});
// Cylinder, cone and torus need normals for their initial values (seed 002);
// without normals they estimate them by PCA of the points (less robust).
FitResult FitCylinder(const FitInput& input, const FitParams& params = {});
FitResult FitCone(const FitInput& input, const FitParams& params = {});
FitResult FitTorus(const FitInput& input, const FitParams& params = {});
// Seed 000 eq. (8): min Σ f(v_i)² + λ Σ |n_i − ∇f(v_i)|², λ = total area
// (weights sum) or point count; linear. Needs normals.
FitResult FitQuadric(const FitInput& input, const FitParams& params = {});

// The local quadratic height function of seed 000 §2:
// h(u, w) = a0 u² + a1 w² + a2 u w + a3 u + a4 w + a5 in the frame
// (origin, u_axis, w_axis, normal), normal = u_axis × w_axis.
struct HeightFunction {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d w_axis = Eigen::Vector3d::UnitY();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::array<double, 6> a{};
  bool valid = false;
};

// Fits h over `points` in the frame at `origin` with normal `normal`
// (weighted least squares if weights are given). valid = false with fewer
// than 6 well-spread points.
HeightFunction FitHeightFunction(std::span<const Eigen::Vector3d> points,
                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                                 std::span<const double> weights = {});

// Approximate closest point on the height-function surface: vertical
// projection, then two steps of "project onto the tangent plane at the foot,
// drop back onto the graph". Normal = the graph's unit normal there (on the
// side of h.normal); distance = (p - foot) . normal.
Projection Project(const HeightFunction& h, const Eigen::Vector3d& p);

// Principal curvatures of the height function's surface at (u, w) = (0, 0)
// from its full first and second fundamental forms (slopes a3, a4 included),
// kappa_max the one of larger absolute value, with their unit directions in
// 3D. Sign: positive where the surface bends towards `normal` (a sphere seen
// with its outward normal has kappa = -1/R).
struct PrincipalCurvatures {
  double kappa_max = 0.0;
  double kappa_min = 0.0;
  Eigen::Vector3d dir_max = Eigen::Vector3d::UnitX();
  Eigen::Vector3d dir_min = Eigen::Vector3d::UnitY();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // surface normal at the origin
};
PrincipalCurvatures CurvaturesAtOrigin(const HeightFunction& h);

}  // namespace meshseg

#endif  // MESHSEG_FIT_H_
