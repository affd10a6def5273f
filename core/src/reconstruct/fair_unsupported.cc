#include "reconstruct/fair_unsupported.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace meshseg::reconstruct_internal {
namespace {

// Conjugate-gradient stopping rule: relative residual, and a cap on the
// iterations (a gap of n rings converges in about n iterations).
constexpr double kTolerance = 1e-8;
constexpr int kMaxIterations = 2000;

// Marks the free vertices that reach a fixed one through free vertices.
std::vector<uint8_t> AnchoredFree(const std::vector<uint8_t>& free, const TriMesh& mesh) {
  std::vector<uint8_t> anchored(free.size(), 0);
  std::vector<int> stack;
  for (const auto v : mesh.vertices()) {
    if (!free[v.idx()]) continue;
    for (const auto w : v.vertices()) {
      if (!free[w.idx()]) {
        anchored[v.idx()] = 1;
        stack.push_back(v.idx());
        break;
      }
    }
  }
  while (!stack.empty()) {
    const TriMesh::VertexHandle v(stack.back());
    stack.pop_back();
    for (const auto w : mesh.vv_range(v)) {
      if (free[w.idx()] && !anchored[w.idx()]) {
        anchored[w.idx()] = 1;
        stack.push_back(w.idx());
      }
    }
  }
  return anchored;
}

}  // namespace

int64_t FairFreeVertices(const std::vector<uint8_t>& free, TriMesh* mesh) {
  const std::vector<uint8_t> moving = AnchoredFree(free, *mesh);
  std::vector<int> unknown(mesh->n_vertices(), -1);
  int n = 0;
  for (size_t v = 0; v < moving.size(); ++v) {
    if (moving[v]) unknown[v] = n++;
  }
  if (n == 0) return 0;
  // L x = b: per free vertex, valence × x_v − Σ free neighbours = Σ fixed ones.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX3d b = Eigen::MatrixX3d::Zero(n, 3);
  Eigen::MatrixX3d x0(n, 3);
  for (const auto v : mesh->vertices()) {
    const int row = unknown[v.idx()];
    if (row < 0) continue;
    x0.row(row) = ToEigen(mesh->point(v)).transpose();
    double valence = 0.0;
    for (const auto w : v.vertices()) {
      valence += 1.0;
      if (unknown[w.idx()] >= 0) {
        entries.emplace_back(row, unknown[w.idx()], -1.0);
      } else {
        b.row(row) += ToEigen(mesh->point(w)).transpose();
      }
    }
    entries.emplace_back(row, row, valence);
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kTolerance);
  cg.setMaxIterations(kMaxIterations);
  cg.compute(laplacian);
  Eigen::MatrixX3d x(n, 3);
  for (int c = 0; c < 3; ++c) x.col(c) = cg.solveWithGuess(b.col(c), x0.col(c));
  for (const auto v : mesh->vertices()) {
    const int row = unknown[v.idx()];
    if (row >= 0) mesh->set_point(v, TriMesh::Point(x(row, 0), x(row, 1), x(row, 2)));
  }
  return n;
}

}  // namespace meshseg::reconstruct_internal
