// "No tuning by default": the noise level and resolution of the mesh, and
// the tolerances of ALGORITHMS.md S1 eqs. (5), (6) derived from them.
#ifndef MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
#define MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_

#include <optional>

#include "meshseg/segment.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Returns the estimates for a mesh with mean edge length `l_avg`, from the
// non-sharp vertices whose pass-2 fit residual is within 1.5 times the most
// common one (the rest straddle an edge):
// noise sigma = their median fit residual;
// th_dis = max(distance_tolerance * l_avg, 3 sigma);
// th_nm = the user's angle, else 1.5 times their median angle between
// n_i and n'_i (the noise-induced scatter of the vertex normals), in [5°, 30°].
SegmentEstimates EstimateNoise(const CurvatureField& curvature, double l_avg,
                               const SegmentParams& params);

// (th_dis / k)^2 / u^2 for `estimates`, u the data term's unit (energy.h,
// "Data unit"): 1 for a mesh as read (`point_noise` unset) or from
// noise-free points (0), whose unit is th_dis / k. For a mesh reconstructed
// from noisy points, u is the vertices' own scatter (estimates.noise_sigma),
// never more than th_dis / k.
double DataUnitScale(const SegmentEstimates& estimates, std::optional<double> point_noise);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
