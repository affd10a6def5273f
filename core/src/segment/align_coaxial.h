// One axis for the surfaces of one turned feature (our addition to
// ALGORITHMS.md S1 and S2; S2's D3 recognises such surfaces of revolution,
// this fits them on one axis). A countersink and the bore below it, a chamfer
// and its shaft, a shaft's steps share their axis by design, but each region
// fitted alone gets its axis from its own vertices only, and a narrow band
// has few: a 45-degree countersink band at sigma = 0.05 h tilted 0.51 degrees
// while the bore beside it was within 0.01. Fitted together, the band takes
// the axis the bore's many rows define.
#ifndef MESHSEG_SRC_SEGMENT_ALIGN_COAXIAL_H_
#define MESHSEG_SRC_SEGMENT_ALIGN_COAXIAL_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Adjacent cylinders and cones whose axes are within kCoaxialMaxAngleDeg
// and pass within kCoaxialMaxOffset of their radii of each other are
// candidates, taken in order of their axis angle. Two groups (a region
// alone is one) become one if FitCoaxial of all their members, on the
// vertices that meet (5) and (6) for their surfaces (sub-sampled), raises
// the sum of squared distances by at most kCoaxialChiSquare times the
// residual variance of the members fitted alone: the 99.9 % quantile of
// chi-square with the 4 values of the axis the constraint fixes, so an axis
// the data tell apart (a tilted or offset hole) keeps its own; or if the
// joint fit meets every member's points at the noise (FitsAtNoise): a
// separate axis must be both significant and larger than the noise can
// hide. A 99.9 % test still rejects 1 true shared axis in 1000, and a
// narrow band's own axis is then far off: a 45-degree chamfer band 6 h
// wide at sigma = 0.15 h, where on its true vertices alone the true cone
// cost 17 to 24 noise variances more than the free one (chi-square with 6
// values: 22.5 at 99.9 %), came out 1.6 to 1.8 degrees off its shaft's
// axis; the shared axis met its points at the noise (rms 0.0525, sigma
// 0.0527).
// Every region of a group of two or more takes the joint fit. Returns those
// groups.
std::vector<std::vector<int>> AlignCoaxialRegions(const SegmentContext& c,
                                                  const std::vector<int>& labels,
                                                  std::vector<RegionState>* regions);

// Adjacent cylinders of one group of AlignCoaxialRegions whose radii differ
// by less than th_dis are one face that growth left in pieces: each merges
// into the largest it matches, whose radius is then the least-squares one
// about the shared axis over the vertices that meet (5) and (6) for its
// surface. A noisy round of r 5 (sigma = 0.15 h) ended in pieces of 126
// and 423 vertices, r 5.35 and 5.14 on one axis, and the face labels cut
// the boundary between them into 4 pieces. Returns the number of merges.
int MergeCoaxialCylinders(const SegmentContext& c, const std::vector<std::vector<int>>& groups,
                          std::vector<int>* labels, std::vector<RegionState>* regions);

// True if the axes of `a` and `b` (surfaces with an axis, AxisOf) are
// within kCoaxialMaxAngleDeg and, at the point of a's axis nearest
// `middle`, within kCoaxialMaxOffset times `radius` of each other.
bool NearlyCoaxial(const Surface& a, const Surface& b, const Eigen::Vector3d& middle,
                   double radius);

inline constexpr double kCoaxialMaxAngleDeg = 5.0;
inline constexpr double kCoaxialMaxOffset = 0.2;
inline constexpr double kCoaxialChiSquare = 18.47;  // chi-square, 4 degrees of freedom, 99.9 %

// The residual variance of fits with `values` free values that leave `cost`
// (the sum of squared distances) over `points` points: cost / (points -
// values), and at least (kVarianceFloor l_avg)^2, as exact input fits to
// rounding. The scale of the kCoaxialChiSquare tests.
double ResidualVariance(const SegmentContext& c, double cost, double points, double values);
inline constexpr double kVarianceFloor = 1e-6;

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ALIGN_COAXIAL_H_
