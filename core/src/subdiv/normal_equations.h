// The normal equations A^T A P = A^T b of one least-squares round of the
// fit (fit_control_points.h), assembled per limit face instead of from the
// rows of A.
#ifndef MESHSEG_SUBDIV_NORMAL_EQUATIONS_H_
#define MESHSEG_SUBDIV_NORMAL_EQUATIONS_H_

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "subdiv/footpoints.h"
#include "subdiv/limit_positions.h"

namespace meshseg::subdiv_internal {

struct NormalEquations {
  Eigen::SparseMatrix<double> ata;  // 3m x 3m, x, y, z of each control vertex in turn
  Eigen::VectorXd atb;
};

// A data point d with footpoint weights b on limit face f contributes the
// row r = sum_c b_c W_c (W_c the limit operator's row of f's vertex c) and,
// with f's unit normal n, the residuals n . (r P - d) and sqrt(alpha)
// (r P - d): minimising squared normal distances (point-to-plane) lets the
// surface slide along itself, so the footpoint rounds converge in a few
// steps where point-to-point needs dozens; the small tangential term keeps
// the system definite (Pottmann et al. 2006). Its share of A^T A is r r^T (x) K_f and of A^T b is
// r (x) K_f d, with K_f = n n^T + alpha I (I on a degenerate face: the
// point-to-point distance), the same for every point of f. Summing the
// barycentric moments sum b b^T and sum b d per face first leaves one
// (stencil x stencil) product per face that holds data, written straight
// into a sparse pattern fixed by the limit surface's topology: no row
// matrix, no sparse-sparse product.
class NormalAssembler {
 public:
  // Collects each limit face's stencil (the control vertices its three
  // limit vertices depend on) and the pattern of A^T A they span.
  explicit NormalAssembler(const LimitSurface& limit);

  // Returns A^T A and A^T b for `feet` of `data` on `limit` (its current
  // vertices give the face normals), tangential weight `alpha`.
  NormalEquations Assemble(const LimitSurface& limit, const std::vector<FootPoint>& feet,
                           const std::vector<Eigen::Vector3d>& data, double alpha) const;

 private:
  int controls_ = 0;
  // Per limit face: its stencil's control vertices (ascending) and the
  // 3 x s weights of its limit vertices on them, row-major.
  std::vector<int> stencil_start_;
  std::vector<int> stencil_;
  std::vector<double> weight_;
  // A^T A's pattern per control vertex (ascending neighbours, itself included).
  std::vector<int> row_start_;
  std::vector<int> row_;
};

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_NORMAL_EQUATIONS_H_
