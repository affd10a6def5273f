// "No tuning by default": the noise level and resolution of the mesh, and
// the tolerances of seed 000 eqs. (5), (6) derived from them.
#ifndef MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
#define MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_

#include "meshseg/segment.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Returns the estimates for a mesh with mean edge length `l_avg`:
// noise sigma = median pass-2 fit residual of non-sharp vertices;
// th_dis = max(distance_tolerance * l_avg, 3 sigma);
// th_nm = the user's angle, else max(5°, the median angle between
// n_i and n'_i), the noise-induced scatter of the vertex normals.
SegmentEstimates EstimateNoise(const CurvatureField& curvature, double l_avg,
                               const SegmentParams& params);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ESTIMATE_NOISE_H_
