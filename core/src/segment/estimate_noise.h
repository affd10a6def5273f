// "No tuning by default": the noise level and resolution of the mesh, and
// the tolerances of ALGORITHMS.md S1 eqs. (5), (6) derived from them.
#ifndef MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
#define MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_

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

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
