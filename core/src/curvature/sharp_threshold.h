// The data-derived sharp-vertex threshold th_sv of seed 000 §2 step 3.
#ifndef MESHSEG_SRC_CURVATURE_SHARP_THRESHOLD_H_
#define MESHSEG_SRC_CURVATURE_SHARP_THRESHOLD_H_

#include <vector>

namespace meshseg::curvature_internal {

// Returns th_sv (in l_i,avg) for a mesh whose pass-1 fits left the rms
// residuals `residual` at vertices with mean edge lengths `edge_length`.
double DeriveSharpThreshold(const std::vector<double>& residual,
                            const std::vector<double>& edge_length);

}  // namespace meshseg::curvature_internal

#endif  // MESHSEG_SRC_CURVATURE_SHARP_THRESHOLD_H_
