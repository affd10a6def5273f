#include "subdiv/data_guard.h"

#include <algorithm>
#include <vector>

namespace meshseg::subdiv_internal {

Eigen::SparseMatrix<double> UmbrellaOperator(const ControlTopology& topo, int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int v = 0; v < n; ++v) {
    const auto& edges = topo.vertex_edges[v];
    for (int k = 0; k < 3; ++k) t.emplace_back(3 * v + k, 3 * v + k, 1.0);
    if (edges.empty()) continue;
    const double w = -1.0 / static_cast<double>(edges.size());
    for (int e : edges) {
      const int u = topo.edges[e][0] == v ? topo.edges[e][1] : topo.edges[e][0];
      for (int k = 0; k < 3; ++k) t.emplace_back(3 * v + k, 3 * u + k, w);
    }
  }
  Eigen::SparseMatrix<double> u(3 * n, 3 * n);
  u.setFromTriplets(t.begin(), t.end());
  return u;
}

GuardTerm DataGuard(const Eigen::SparseMatrix<double>& umbrella,
                    const Eigen::SparseMatrix<double>& data_normal, const Eigen::VectorXd& prior,
                    double fraction) {
  const int n = static_cast<int>(data_normal.rows() / 3);
  GuardTerm out{Eigen::SparseMatrix<double>(3 * n, 3 * n), Eigen::VectorXd::Zero(3 * n)};
  if (!(fraction > 0.0) || n == 0) return out;
  const Eigen::VectorXd diagonal = data_normal.diagonal();
  std::vector<double> weight(n);
  for (int v = 0; v < n; ++v) weight[v] = diagonal.segment<3>(3 * v).mean();
  std::vector<double> sorted = weight;
  const auto mid = sorted.begin() + n / 2;
  std::nth_element(sorted.begin(), mid, sorted.end());
  const double floor = fraction * *mid;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(3 * n);
  for (int v = 0; v < n; ++v) {
    if (weight[v] >= floor) continue;
    c.segment<3>(3 * v).setConstant(floor - weight[v]);
    ++out.guarded;
  }
  if (out.guarded == 0) return out;
  const Eigen::SparseMatrix<double> weighted = c.asDiagonal() * umbrella;
  out.matrix = umbrella.transpose() * weighted;
  out.rhs = out.matrix * prior;
  return out;
}

}  // namespace meshseg::subdiv_internal
