// One local height-function fit of seed 000 §2 at a vertex: the quadratic
// h(u, w) over a neighbourhood in the tangent frame of n_i, its principal
// curvatures at v_i and the rms residual of the fit.
#ifndef MESHSEG_SRC_CURVATURE_LOCAL_FIT_H_
#define MESHSEG_SRC_CURVATURE_LOCAL_FIT_H_

#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/fit.h"

namespace meshseg::curvature_internal {

struct LocalFit {
  PrincipalCurvatures curvatures;
  double residual = 0.0;  // weighted rms of height residuals, model units
  bool valid = false;
};

// Fits h over the vertices `neighborhood` (indices into `positions`, the
// first is the centre vertex) in the frame of `normal`, weighted by `area`.
// `local` (the neighbours in the fit's frame) and `weights` are scratch
// buffers reused between calls.
LocalFit FitAtVertex(std::span<const Eigen::Vector3d> positions, std::span<const double> area,
                     std::span<const int> neighborhood, const Eigen::Vector3d& normal,
                     std::vector<Eigen::Vector3d>* local, std::vector<double>* weights);

}  // namespace meshseg::curvature_internal

#endif  // MESHSEG_SRC_CURVATURE_LOCAL_FIT_H_
