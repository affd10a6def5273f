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
// fits no cylinder is an answer (large errors), not an error; degenerate
// input (too few / collinear points, all normals parallel where the axis
// comes from them, missing normals where required) yields ok() == false and
// finite numbers, never NaN. All functions are pure and deterministic; none
// allocates per point inside its iterations.
//
// Normals: unit normals n'_i, either orientation (outward for a solid's
// skin, inward for a hole); the fitted surface's own normal convention is
// fixed (outward from the axis / centre / tube centre; ∇f for the quadric).
#ifndef MESHSEG_FIT_H_
#define MESHSEG_FIT_H_

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/surface.h"

namespace meshseg {

struct FitParams {
  // Max Levenberg–Marquardt iterations of the geometric refinement.
  int max_iterations = 30;
  // Stop when the relative decrease of the squared error is below this.
  double relative_tolerance = 1e-10;
  // Refine the linear initial fit by geometric distance (seed 000 §5): LM for
  // sphere, cylinder, cone, torus; orthogonal regression for the plane; the
  // parallel-gradient eigenproblem for the quadric. false = seed 002's fast
  // linear fits only (a cone without normals then has no angle: invalid).
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
  int iterations = 0;         // refinement iterations used (0 = linear fit kept)
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
// (the vertex normal n_i; zero vector = use the gradient at p). Normals:
// plane as given; sphere, cylinder, cone outward from the centre / axis;
// torus outward from the tube centre; quadric ∇f / |∇f|. The cone is the one
// nappe on the axis side; behind the apex the apex is the closest point. On an
// axis or at a centre (no unique foot point) the radial direction is taken
// from hint_direction, else chosen deterministically; results stay finite.
Projection Project(const Surface& surface, const Eigen::Vector3d& p,
                   const Eigen::Vector3d& hint_direction = Eigen::Vector3d::Zero());

// Signed distance from p to the surface: Project(surface, p,
// hint_direction).distance, the same to the bit, without the foot point and
// normal (only the torus needs the radial direction, and so the hint).
double SignedDistance(const Surface& surface, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& hint_direction = Eigen::Vector3d::Zero());

// SignedDistance to one surface for many points: what depends on the
// surface alone (its unit normal or axis, a cone's sine and cosine) is
// computed once, the same values each call would compute, so every
// distance is SignedDistance's to the bit.
class SurfaceDistance {
 public:
  explicit SurfaceDistance(const Surface& surface);
  double operator()(const Eigen::Vector3d& p,
                    const Eigen::Vector3d& hint_direction = Eigen::Vector3d::Zero()) const;

 private:
  Surface surface_;
  Eigen::Vector3d unit_ = Eigen::Vector3d::UnitZ();  // the plane's normal or the axis
  double sin_angle_ = 0.0;  // a cone's half angle
  double cos_angle_ = 1.0;
};

// Plane: >= 3 non-collinear points; normal oriented like the mean normal.
FitResult FitPlane(const FitInput& input, const FitParams& params = {});
// Sphere: >= 4 points not all in one plane; normals not used.
FitResult FitSphere(const FitInput& input, const FitParams& params = {});
// Cylinder (>= 5 points) and cone (>= 6) take their initial axis from the
// normals (seed 002); without normals each principal axis of the points is
// tried as the initial axis and the best refined fit is kept (3x the cost).
// Cylinder: axis_origin is the axis point nearest the points' centroid.
// Cone: axis points from the apex into the data; ok() == false when the fit
// degenerates to a cylinder (half angle ~ 0, apex at infinity).
FitResult FitCylinder(const FitInput& input, const FitParams& params = {});
FitResult FitCone(const FitInput& input, const FitParams& params = {});

// How much wider `cone` is at one end of `points` than at the other: their
// extent along its axis times tan(half angle). A cone widening less than the
// distance tolerance over its region is a cylinder within it.
double ConeWidening(const Cone& cone, std::span<const Eigen::Vector3d> points);
// Torus: >= 8 points, needs normals (Kós et al. initial axis, seed 002).
FitResult FitTorus(const FitInput& input, const FitParams& params = {});
// Seed 000 eq. (8): min Σ f(v_i)² + λ Σ |n_i − ∇f(v_i)|², λ = total area
// (weights sum) or, without weights, s² (s = RMS distance of the points from
// their centroid); linear. Needs normals and >= 10 points. See FitParams
// for the refinement. Coefficients scaled so mean |∇f| over the points = 1.
FitResult FitQuadric(const FitInput& input, const FitParams& params = {});
// The fit of `type` above (kFreeform: the quadric).
FitResult FitOfType(SurfaceType type, const FitInput& input, const FitParams& params = {});

// The cylinder of a round between two flat faces: tangent to planes `a` and
// `b`, its axis along their line of intersection, at distance r from each
// on the side `sides` gives (+1: the side its normal points to, -1: the
// other). r, the one value left, is fitted by geometric distance from
// `initial_radius`; weights apply, normals are not used. axis_origin is the
// axis point in the plane across it through the points' centroid. Invalid
// for fewer than 2 points, planes within 0.06 degrees of parallel, an
// initial radius <= 0 or a fit that leaves r <= 0.
FitResult FitCylinderTangentToPlanes(const FitInput& input, const Plane& a, const Plane& b,
                                     std::array<int, 2> sides, double initial_radius,
                                     const FitParams& params = {});

// Cylinders and cones around one axis (a countersink and its bore, a chamfer
// and its shaft) fitted together by geometric distance: one axis line, each
// member its own radius and, for a cone, half angle. Levenberg–Marquardt
// from the line through `axis_origin` along `axis_direction`; each member
// starts from the least-squares line rho = r + h tan(angle) of its points
// about it (a cylinder: r = mean rho). Weights apply; normals are not used.
// Returns one result per member, in order (cylinder axis_origin: the axis
// point nearest the member's centroid); every result is invalid if a member
// is of another type or has too few points (cylinder 5, cone 6, as alone),
// or a cone comes out with a half angle of ~0.
struct CoaxialMember {
  SurfaceType type = SurfaceType::kCylinder;
  FitInput input;
};
std::vector<FitResult> FitCoaxial(std::span<const CoaxialMember> members,
                                  const Eigen::Vector3d& axis_origin,
                                  const Eigen::Vector3d& axis_direction,
                                  const FitParams& params = {});

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
// (weighted least squares if weights are given; u_axis is chosen
// deterministically from the normal). valid = false with fewer than 6
// well-spread points (e.g. all on one line) or a zero normal; a is then zero.
HeightFunction FitHeightFunction(std::span<const Eigen::Vector3d> points,
                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                                 std::span<const double> weights = {});

// The two halves of FitHeightFunction, for callers that hold the points in
// the frame already (a local fit at every vertex of a mesh reuses them for
// its residuals). HeightFrame: h with its origin and axes set and a zero,
// valid = false; false for a zero or non-finite normal.
bool HeightFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, HeightFunction* h);
// Fits h->a to points given in h's frame, local[i] = ((p - o)·u, (p - o)·w,
// (p - o)·n) for p = points[i]; sets h->valid. Same result, bit for bit, as
// FitHeightFunction on the points.
void FitHeightInFrame(std::span<const Eigen::Vector3d> local, std::span<const double> weights,
                      HeightFunction* h);

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
