#include "subdiv/loop_refine.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace meshseg::subdiv_internal {

double LoopBeta(int n) {
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * std::numbers::pi / n);
  return (5.0 / 8.0 - c * c) / n;
}

void AppendVertexRules(const ControlTopology& topo, std::vector<Eigen::Triplet<double>>& w) {
  const int n = static_cast<int>(topo.kind.size());
  for (int v = 0; v < n; ++v) {
    const auto& ring = topo.vertex_edges[v];
    switch (topo.kind[v]) {
      case VertexKind::kCorner:
        w.emplace_back(v, v, 1.0);
        break;
      case VertexKind::kCrease:
        w.emplace_back(v, v, 0.75);
        for (int e : ring) {
          if (!topo.sharp[e]) continue;
          const int u = topo.edges[e][0] == v ? topo.edges[e][1] : topo.edges[e][0];
          w.emplace_back(v, u, 0.125);
        }
        break;
      case VertexKind::kSmooth: {
        const int k = static_cast<int>(ring.size());
        const double beta = LoopBeta(k);
        w.emplace_back(v, v, 1.0 - k * beta);
        for (int e : ring) {
          const int u = topo.edges[e][0] == v ? topo.edges[e][1] : topo.edges[e][0];
          w.emplace_back(v, u, beta);
        }
        break;
      }
    }
  }
}

SparseMatrix VertexRules(const ControlTopology& topo) {
  const int n = static_cast<int>(topo.kind.size());
  std::vector<Eigen::Triplet<double>> w;
  AppendVertexRules(topo, w);
  SparseMatrix rules(n, n);
  rules.setFromTriplets(w.begin(), w.end());
  return rules;
}

LoopLevel RefineLoop(const ControlMesh& mesh, const ControlTopology& topo) {
  const int n = static_cast<int>(mesh.vertices.size());
  const int ne = static_cast<int>(topo.edges.size());
  std::vector<Eigen::Triplet<double>> w;
  w.reserve(static_cast<size_t>(n) * 7 + static_cast<size_t>(ne) * 4);
  AppendVertexRules(topo, w);
  for (int e = 0; e < ne; ++e) {
    const int row = n + e;
    const auto [a, b] = topo.edges[e];
    if (topo.sharp[e]) {
      w.emplace_back(row, a, 0.5);
      w.emplace_back(row, b, 0.5);
      continue;
    }
    w.emplace_back(row, a, 0.375);
    w.emplace_back(row, b, 0.375);
    w.emplace_back(row, topo.opposite[e][0], 0.125);
    w.emplace_back(row, topo.opposite[e][1], 0.125);
  }
  LoopLevel level;
  level.subdivision.resize(n + ne, n);
  level.subdivision.setFromTriplets(w.begin(), w.end());

  ControlMesh& fine = level.mesh;
  fine.vertices.resize(n + ne);
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> coarse(
      mesh.vertices.empty() ? nullptr : mesh.vertices[0].data(), n, 3);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> refined =
      level.subdivision * coarse;
  for (int i = 0; i < n + ne; ++i) fine.vertices[i] = refined.row(i).transpose();
  fine.faces.reserve(mesh.faces.size() * 4);
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    const auto& fe = topo.face_edges[f];
    const int m01 = n + fe[0], m12 = n + fe[1], m20 = n + fe[2];
    fine.faces.push_back({t[0], m01, m20});
    fine.faces.push_back({t[1], m12, m01});
    fine.faces.push_back({t[2], m20, m12});
    fine.faces.push_back({m01, m12, m20});
  }
  for (int e = 0; e < ne; ++e) {
    if (!topo.sharp[e] || topo.opposite[e][1] == -1) continue;  // boundary halves stay boundary
    fine.creases.push_back({topo.edges[e][0], n + e});
    fine.creases.push_back({n + e, topo.edges[e][1]});
  }
  for (int v = 0; v < n; ++v) {
    if (topo.kind[v] == VertexKind::kCorner) fine.corners.push_back(v);
  }
  return level;
}

}  // namespace meshseg::subdiv_internal
