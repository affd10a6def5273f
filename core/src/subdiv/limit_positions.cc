#include "subdiv/limit_positions.h"

#include <Eigen/Dense>

#include "absl/container/flat_hash_map.h"
#include "meshseg/status_macros.h"

namespace meshseg::subdiv_internal {
namespace {

int Other(const std::array<int, 2>& edge, int v) { return edge[0] == v ? edge[1] : edge[0]; }

// The subdivision matrix of v's 1-ring: local index 0 is v, 1..k its
// neighbours in vertex_edges order; row j > 0 is the point of edge (v, u_j).
Eigen::MatrixXd LocalSubdivision(const ControlTopology& topo, int v,
                                 const SparseMatrix& vertex_rows) {
  const auto& ring = topo.vertex_edges[v];
  const int k = static_cast<int>(ring.size());
  absl::flat_hash_map<int, int> local;
  local[v] = 0;
  for (int j = 0; j < k; ++j) local[Other(topo.edges[ring[j]], v)] = j + 1;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(k + 1, k + 1);
  for (SparseMatrix::InnerIterator it(vertex_rows, v); it; ++it)
    s(0, local.at(it.col())) = it.value();
  for (int j = 0; j < k; ++j) {
    const int e = ring[j];
    if (topo.sharp[e]) {
      s(j + 1, 0) = s(j + 1, j + 1) = 0.5;
      continue;
    }
    s(j + 1, 0) = s(j + 1, j + 1) = 0.375;
    // The opposite vertices of a smooth edge at v are neighbours of v.
    for (int c : topo.opposite[e]) s(j + 1, local.at(c)) += 0.125;
  }
  return s;
}

}  // namespace

SparseMatrix LimitMasks(const ControlTopology& topo) {
  const int n = static_cast<int>(topo.kind.size());
  const SparseMatrix vertex_rows = VertexRules(topo);
  std::vector<Eigen::Triplet<double>> w;
  for (int v = 0; v < n; ++v) {
    if (topo.kind[v] == VertexKind::kCorner) {
      w.emplace_back(v, v, 1.0);
      continue;
    }
    const Eigen::MatrixXd s = LocalSubdivision(topo, v, vertex_rows);
    const int m = static_cast<int>(s.rows());
    // l^T S = l^T and sum(l) = 1, solved as one consistent least-squares system.
    Eigen::MatrixXd a(m + 1, m);
    a.topRows(m) = s.transpose() - Eigen::MatrixXd::Identity(m, m);
    a.row(m).setOnes();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
    rhs(m) = 1.0;
    const Eigen::VectorXd l = a.colPivHouseholderQr().solve(rhs);
    const auto& ring = topo.vertex_edges[v];
    w.emplace_back(v, v, l(0));
    for (int j = 0; j < m - 1; ++j) w.emplace_back(v, Other(topo.edges[ring[j]], v), l(j + 1));
  }
  SparseMatrix masks(n, n);
  masks.setFromTriplets(w.begin(), w.end());
  return masks;
}

absl::StatusOr<LimitSurface> SampleLimitSurface(const ControlMesh& control, int level) {
  LimitSurface out;
  out.mesh = control;
  const int n = static_cast<int>(control.vertices.size());
  SparseMatrix to_level(n, n);
  to_level.setIdentity();
  MESHSEG_ASSIGN_OR_RETURN(ControlTopology topo, BuildControlTopology(out.mesh));
  for (int l = 0; l < level; ++l) {
    LoopLevel next = RefineLoop(out.mesh, topo);
    to_level = (next.subdivision * to_level).pruned();
    out.mesh = std::move(next.mesh);
    MESHSEG_ASSIGN_OR_RETURN(topo, BuildControlTopology(out.mesh));
  }
  out.from_control = (LimitMasks(topo) * to_level).pruned();
  out.mesh.vertices = Apply(out.from_control, control.vertices);
  return out;
}

std::vector<Eigen::Vector3d> Apply(const SparseMatrix& rows,
                                   const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> out(rows.rows(), Eigen::Vector3d::Zero());
  for (int r = 0; r < rows.outerSize(); ++r) {
    for (SparseMatrix::InnerIterator it(rows, r); it; ++it) out[r] += it.value() * points[it.col()];
  }
  return out;
}

}  // namespace meshseg::subdiv_internal
