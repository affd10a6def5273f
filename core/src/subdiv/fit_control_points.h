// Control-vertex positions whose Loop limit surface fits data points:
// quasi-interpolation (a linear first guess) as the start, then rounds of footpoint
// update and sparse linear least squares (Hoppe et al. 1994 section 5).
#ifndef MESHSEG_SUBDIV_FIT_CONTROL_POINTS_H_
#define MESHSEG_SUBDIV_FIT_CONTROL_POINTS_H_

#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "meshseg/subdiv.h"
#include "subdiv/control_topology.h"
#include "subdiv/limit_positions.h"

namespace meshseg::subdiv_internal {

// Returns `control` with each vertex moved by its own offset from its limit
// position, v + (v - limit(v)): the first-order inverse of the limit masks.
// For a regular smooth vertex (limit mask 1/2, 1/12 each) this is
// v <- (1 - k gamma) v + gamma sum v_j with gamma = -1/(2k); for
// other valences, creases and corners it uses the vertex's own mask, so a
// corner stays and a crease vertex moves along its crease curve's inverse.
std::vector<Eigen::Vector3d> QuasiInterpolate(const ControlMesh& control,
                                              const ControlTopology& topo);

struct ControlFit {
  std::vector<Eigen::Vector3d> vertices;  // fitted control vertices
  LimitSurface limit;                     // their limit surface at the fit's level
  double rms_distance = 0.0;              // data -> limit surface
  double max_distance = 0.0;
  std::vector<double> rms_per_round;  // start, then after each round
  std::vector<int> guarded_per_round;  // vertices the data guard held, per round
};

// Returns the control vertices of `control` (its topology and tags kept)
// fitted to `data` through the limit surface sampled at `level`: each round
// finds every data point's footpoint on the limit surface and solves the
// linear least-squares problem
//   min sum_i ((n_i . (B_i P - d_i))^2 + alpha |B_i P - d_i|^2) / |D| + w |G P|^2 / |E|
//       + sum_v c_v |U_v (P - P_0)|^2,
// B_i the footpoint's row of the limit operator, n_i the limit surface's
// normal there, alpha = `tangent_weight`, G the control edges' differences,
// w = `smoothing_weight`, U the umbrella operator, P_0 = `control`'s
// vertices and c_v the data guard's weights for `guard_fraction`
// (data_guard.h): the normal equations assembled per limit face
// (normal_equations.h), solved by Jacobi-preconditioned conjugate gradients
// started from the previous round's control vertices (a sparse Cholesky
// factorisation if they do not converge).
// Errors: those of BuildControlTopology; INTERNAL if the system cannot be
// factored; CANCELLED on stop.
absl::StatusOr<ControlFit> FitControlPoints(const ControlMesh& control,
                                            const std::vector<Eigen::Vector3d>& data, int level,
                                            int rounds, double smoothing_weight,
                                            double tangent_weight, double guard_fraction = 0.0,
                                            const RunContext& ctx = {});

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_FIT_CONTROL_POINTS_H_
