// Proofs that no sphere, or no cylinder of an admissible axis, passes within
// tau of every one of a set of points: an exact fit (FitExactly accepts a
// surface only with every corner within tau) that such a proof excludes
// must fail, and need not be run. A proof, never a guess: true only when
// the inequality below holds with a margin for rounding; false says nothing.
//
// Principle (Pratt's normalisation of the algebraic sphere). A sphere of
// centre c and radius R is the zero set of
//   Q(p) = alpha |p|^2 + b . p + g,  alpha = 1/R, b = -2c/R, g = (|c|^2 - R^2)/R,
// whose coefficients x = (alpha, b, g) satisfy x^T B x = |b|^2 - 4 alpha g = 4
// for every sphere, and Q(p) = 2d + d^2/R exactly at a point at distance d
// from it. Points within tau of a sphere of radius R >= R_min (a bound the
// points' spread gives) thus have |Q(p_i)| <= eps = 2 tau + tau^2 / R_min,
// and x^T M x = sum Q(p_i)^2 <= N eps^2 (M = sum z_i z_i^T, z = (|p|^2, p, 1)).
// If M - (N eps^2 / 4) B is positive definite, every x with x^T B x = 4 has
// x^T M x > N eps^2: no sphere is that close to every point.
// A cylinder of axis a is the same with |p|^2 replaced by |P_a p|^2 (P_a =
// I - a a^T): Q(p) = 2d + d^2/R again, with d the distance from the
// cylinder. Its axis is known to within an angle w of a direction e when
// the facet normals bound |n . a| (exact_fit.cc: FitExactly accepts
// only cylinders as perpendicular to the normals as they allow); then
// | |P_e p|^2 - |P_a p|^2 | = |p.(e - a)| |p.(e + a)| <= ((1 - cos w) |p.e| +
// sin w |P_e p|) (2 |p.e| + sin w |P_e p|) adds that over R_min to eps (the
// part of a across e is at most sin w long, and perpendicular to e).
#ifndef MESHSEG_SRC_SEGMENT_FIT_EXCLUSION_H_
#define MESHSEG_SRC_SEGMENT_FIT_EXCLUSION_H_

#include <Eigen/Core>
#include <span>

namespace meshseg::segment_internal {

// True if no quadric surface (plane, sphere, cylinder, cone, ...) passes
// within `tau` of every point of `points`. A point p within tau of the zero
// set of Q(p) = p^T A p + b . p + c has |Q(p)| <= tau |grad Q(p)| + 3 |A|
// tau^2 (Taylor at the nearest point of the surface, exact for a
// quadratic), so sum Q(p_i)^2 <= x^T (2 tau^2 K + 18 N tau^4 E) x for the
// coefficients x (K = sum of the gradients' Gram matrices, x^T E x =
// |A|_F^2); if M minus that is positive definite, no coefficients do it.
// Corners on two parallel planes (rim to rim strips) lie on the quadric of
// that pair of planes: no proof for them.
bool NoQuadricWithin(std::span<const Eigen::Vector3d> points, double tau);

// What the quadric form above says of cylinders (any axis) and cones near
// `points`: true where none passes within `tau` of every point.
struct AxialExclusion {
  bool cylinder = false;
  bool cone = false;
};

// The cylinders and cones (one nappe: the surface FitExactly accepts, a
// half-line turned about the axis) that the quadric form excludes, even
// where a pair of planes or another quadric passes (corners on two rims).
// The fitting quadrics x (x^T H x <= 0, H as in NoQuadricWithin) are shown
// to lie near one line u; a cylinder's or cone's A = sigma (I - k a a^T)
// has a double eigenvalue, which u's A, dominated by one eigenvalue (the
// pair of planes n n^T), keeps far from it unless sigma is small and k
// large: a nearly flat cone about n, one nappe of which is a graph of
// small slope over the plane across n, and cannot reach points far apart
// along n. The steps and their bounds are in fit_exclusion.cc. The last
// answer is kept per thread (a seed group is asked about as a cylinder,
// then as a cone).
AxialExclusion ExcludeAxial(std::span<const Eigen::Vector3d> points, double tau);

// True if no sphere passes within `tau` of every point of `points`.
bool NoSphereWithin(std::span<const Eigen::Vector3d> points, double tau);

// True if no cylinder passes within `tau` of every point of `points` with an
// axis a for which |n . a| <= max_tilt for every n of `normals` (unit, or
// zero for a degenerate facet).
bool NoCylinderWithin(std::span<const Eigen::Vector3d> points,
                      std::span<const Eigen::Vector3d> normals, double max_tilt, double tau);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FIT_EXCLUSION_H_
