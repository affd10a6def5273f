// One axis for the surfaces of one turned feature (our addition to seeds 000
// and 002). A countersink and the bore below it, a chamfer and its shaft, a
// shaft's steps share their axis by design, but each region fitted alone
// gets its axis from its own vertices only, and a narrow band has few:
// test_piece's 45-degree countersink at 0.05 h (seed 54) tilts 0.51 degrees
// while the bore beside it is within 0.01. Fitted together, the band takes
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
// the data tell apart (a tilted or offset hole) keeps its own. Every region
// of a group of two or more takes the joint fit. Returns the number of
// regions whose surface changed.
int AlignCoaxialRegions(const SegmentContext& c, const std::vector<int>& labels,
                        std::vector<RegionState>* regions);

// True if the axes of `a` and `b` (surfaces with an axis, AxisOf) are
// within kCoaxialMaxAngleDeg and, at the point of a's axis nearest
// `middle`, within kCoaxialMaxOffset times `radius` of each other.
bool NearlyCoaxial(const Surface& a, const Surface& b, const Eigen::Vector3d& middle,
                   double radius);

inline constexpr double kCoaxialMaxAngleDeg = 5.0;
inline constexpr double kCoaxialMaxOffset = 0.2;
inline constexpr double kCoaxialChiSquare = 18.47;  // chi-square, 4 degrees of freedom, 99.9 %

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ALIGN_COAXIAL_H_
