// Sharp creases of the sampled surface (issue 38 item 3: "sharp edges
// kept"). Near an edge of a machined part the points lie on two surfaces
// that meet at an angle. One least-squares plane through such a
// neighbourhood (the moving-least-squares projection, project_to_points.h)
// or one linear function per support (the partition of unity of
// ALGORITHMS.md S3) averages the two and rounds the edge off over the fit's
// radius. Here, as in the sharp-feature functions of multi-level partition
// of unity (Ohtake et al. 2003, "Multi-level partition of unity implicits",
// §3: a local fit that models two surfaces, combined by min or max, where
// the normals in a cell split into two groups), the neighbourhood is fitted
// by two planes when its normals split into two groups at an angle and two
// planes explain the points clearly better than one. The solid near the
// crease is the intersection of the two inner half-spaces (a convex edge)
// or their union (a concave one), so the surface is the zero set of
// min(g0, g1) or max(g0, g1), g_k the signed distance to plane k: the edge
// stays sharp, and a vertex on it is projected onto the planes' line.
// ALGORITHMS.md S3 step 7 asks the same of the smoothing:
// the detail the fits resolve is kept as it is.
#ifndef MESHSEG_RECONSTRUCT_CREASE_H_
#define MESHSEG_RECONSTRUCT_CREASE_H_

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// Two planes meeting at a crease, normals unit and pointing into the solid.
struct Crease {
  Eigen::Vector3d point[2];
  Eigen::Vector3d normal[2];
  bool convex = true;  // the solid is both inner half-spaces (else either)

  // Signed distance to plane k, positive inside.
  double g(int k, const Eigen::Vector3d& x) const { return normal[k].dot(x - point[k]); }
  // The plane (0 or 1) whose part of the surface lies on x's side of the
  // bisecting plane g0 = g1 through the crease line.
  int Side(const Eigen::Vector3d& x) const;
  // The point of the crease line nearest to x.
  Eigen::Vector3d OntoLine(const Eigen::Vector3d& x) const;
  // The point of the surface min(g0, g1) = 0 (convex) or max(g0, g1) = 0
  // (concave) nearest to x: on plane 0's part, plane 1's part, or the line.
  Eigen::Vector3d Nearest(const Eigen::Vector3d& x) const;
};

// Normals in a neighbourhood all within this angle of one another's mean
// (half of it from the mean) are one surface. 30°: a cylinder of radius R
// turns its normal by r / R over a fit of radius r, so a crease is never
// seen on a cylinder of more than ~2 fit radii; a 45° chamfer's edges are.
inline constexpr double kMinCreaseAngleDeg = 30.0;
// Two planes are taken when one plane leaves a misfit beyond the noise (its
// weighted rms residual over kPlaneNoiseFit σ, σ the cloud's noise
// (outliers.h): for Gaussian residuals about one plane the rms is σ) and two
// planes explain most of it (their rms at most kCreaseResidualRatio of one
// plane's). Two planes at 30° or more fitted to noise about one plane, each
// point to the nearer, also lower the rms, by up to about half on noisy
// scans: the first condition keeps them out. 1.5 σ, not more: a vertex a few
// spacings from an edge sees a handful of the other face's points, which
// raise one plane's rms to 1.3-2.3 σ on a lightly noisy sample (σ 0.2 sp).
// A curved patch whose normals turn by more than kMinCreaseAngleDeg within
// the fit (radius R < ~2 r) passes too; the two planes then follow it within
// the sag of half a chord, r² / (8 R), less than one plane's r² / (2 R).
inline constexpr double kPlaneNoiseFit = 1.5;
inline constexpr double kCreaseResidualRatio = 0.5;

// Creases are kept on clean and lightly noisy clouds (issue 38 item 3): noise
// σ up to this many point spacings h. Beyond it the gate above cannot tell a
// crease from noise (the cloud's σ, measured about local planes, runs low on
// scans; on the shared ABC scan, σ 0.38 h, it took noise for creases and
// moved the accuracy p95 by +0.14 sp over four draws), and the two planes'
// line is no better placed than one plane's rounding (the generated hard
// clouds, σ ~0.2 h with 5 % outliers: more vertices farther than h / 2).
inline constexpr double kMaxCreaseNoise = 0.15;

// Returns the two planes that model the points `at` (inward unit normals
// `normal`, weights `weight`, all of one length; noise σ `noise` about the
// surface, model units), or nothing when one plane models them as well (see
// kMinCreaseAngleDeg, kPlaneNoiseFit, kCreaseResidualRatio) or a plane has
// fewer than 3 points.
std::optional<Crease> FitCrease(const std::vector<Eigen::Vector3d>& at,
                                const std::vector<Eigen::Vector3d>& normal,
                                const std::vector<double>& weight, double noise = 0.0);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CREASE_H_
