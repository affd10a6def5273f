// Where the vertices of a control mesh go in the limit of Loop subdivision,
// as a sparse matrix, and the limit surface sampled at a subdivision level.
#ifndef MESHSEG_SUBDIV_LIMIT_POSITIONS_H_
#define MESHSEG_SUBDIV_LIMIT_POSITIONS_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/subdiv.h"
#include "subdiv/control_topology.h"
#include "subdiv/loop_refine.h"

namespace meshseg::subdiv_internal {

// Returns the limit masks of `topo`'s vertices: row v holds the weights of v
// and its neighbours whose sum is v's limit position. The 1-ring of a vertex
// maps onto the 1-ring of its refined self under every rule of RefineLoop, so
// the limit position is the left eigenvector of that local subdivision matrix
// for eigenvalue 1, scaled to unit sum (Halstead et al. 1993; Hoppe et al.
// 1994 section 3.2). This gives the closed forms (regular vertex: 1/2 and
// 1/12 each; crease: 2/3 and 1/6 along the crease; corner: 1) and the
// right mask for darts and crease vertices with any number of smooth edges.
SparseMatrix LimitMasks(const ControlTopology& topo);

// The limit surface sampled at subdivision level `level` (>= 0).
struct LimitSurface {
  // The level's mesh; its vertices are the exact limit positions.
  ControlMesh mesh;
  // mesh.vertices = from_control * (control vertices), row by row.
  SparseMatrix from_control;
};

// Returns the limit surface of `control` at `level`.
// Errors: those of BuildControlTopology.
absl::StatusOr<LimitSurface> SampleLimitSurface(const ControlMesh& control, int level);

// Returns `rows` times the n x 3 matrix of `points`.
std::vector<Eigen::Vector3d> Apply(const SparseMatrix& rows,
                                   const std::vector<Eigen::Vector3d>& points);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_LIMIT_POSITIONS_H_
