// One level of Loop subdivision with Hoppe et al. 1994 crease and corner
// rules, as a sparse matrix from coarse to fine vertex positions.
#ifndef MESHSEG_SUBDIV_LOOP_REFINE_H_
#define MESHSEG_SUBDIV_LOOP_REFINE_H_

#include <vector>

#include <Eigen/SparseCore>

#include "meshseg/subdiv.h"
#include "subdiv/control_topology.h"

namespace meshseg::subdiv_internal {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct LoopLevel {
  // The refined mesh: coarse vertex v stays vertex v; the point of coarse
  // edge e is vertex (coarse vertex count + e). Each face splits into four;
  // each sharp edge into two sharp halves; corners keep their tag.
  ControlMesh mesh;
  // fine vertex count x coarse vertex count: fine = subdivision * coarse.
  SparseMatrix subdivision;
};

// Loop's smooth-vertex weight for valence n (Loop 1987):
// beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
double LoopBeta(int n);

// Appends the vertex rules of RefineLoop (rows 0..n-1) to `w`.
void AppendVertexRules(const ControlTopology& topo, std::vector<Eigen::Triplet<double>>& w);

// Returns the n x n matrix of RefineLoop's vertex rules: where each vertex
// moves, from its own and its neighbours' positions.
SparseMatrix VertexRules(const ControlTopology& topo);

// Returns one Loop refinement of `mesh` (whose topology is `topo`). Rules
// (Hoppe et al. 1994 table 1): smooth vertex (1 - n beta) v + beta sum v_j;
// crease vertex 3/4 v + 1/8 (a + b) over its two sharp neighbours; corner v;
// smooth edge 3/8 (a + b) + 1/8 (c + d); sharp edge 1/2 (a + b).
LoopLevel RefineLoop(const ControlMesh& mesh, const ControlTopology& topo);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_LOOP_REFINE_H_
