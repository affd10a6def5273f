// A guard for control vertices that the data hardly reach: a thin-plate
// (umbrella) prior on their displacement, weighted by the data weight they
// lack (fit_control_points.h).
//
// A control vertex whose limit-surface support holds few data points, or
// holds them only where its basis function is small, is determined by the
// data only weakly: the least squares move it far for a small gain (a flap
// of the limit surface beside the data, typically next to a crease or at a
// thin part). The data weight a vertex receives is the diagonal of the
// data's normal equations at it (sum over data points of its basis value
// squared, times the point's weight); where it is below a fraction of the
// median vertex's, the shortfall is made up by a prior that keeps the
// vertex's umbrella vector (its offset from the mean of its neighbours) as
// in the starting control mesh: the vertex moves with its neighbours
// instead of drifting. Vertices with enough data are not touched.
#ifndef MESHSEG_SUBDIV_DATA_GUARD_H_
#define MESHSEG_SUBDIV_DATA_GUARD_H_

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "subdiv/control_topology.h"

namespace meshseg::subdiv_internal {

// The umbrella operator of a control mesh of n vertices, per coordinate:
// row 3v + k is (P_v - mean of v's neighbours)_k.
Eigen::SparseMatrix<double> UmbrellaOperator(const ControlTopology& topo, int n);

struct GuardTerm {
  Eigen::SparseMatrix<double> matrix;  // U^T C U, to add to the normal matrix
  Eigen::VectorXd rhs;                 // U^T C U prior, to add to the right-hand side
  int guarded = 0;                     // vertices with a positive weight
};

// Returns sum_v c_v |U_v (P - prior)|^2 as normal-equation terms, with
// c_v = max(0, fraction * median_w - w_v) and w_v the mean of the three
// diagonal entries of `data_normal` (the data's normal matrix, 3n x 3n) at
// vertex v: every vertex gets at least `fraction` of the median vertex's
// weight on its own position. fraction 0 = no guard.
GuardTerm DataGuard(const Eigen::SparseMatrix<double>& umbrella,
                    const Eigen::SparseMatrix<double>& data_normal, const Eigen::VectorXd& prior,
                    double fraction);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_DATA_GUARD_H_
