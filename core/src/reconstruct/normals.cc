#include "reconstruct/normals.h"

#include <algorithm>
#include <cstdint>
#include <queue>
#include <tuple>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: normals";

// Symmetric k-NN graph in compressed rows: neighbours of i are
// adj[offset[i] .. offset[i + 1]).
struct KnnGraph {
  std::vector<uint32_t> offset;
  std::vector<uint32_t> adj;
};

// Returns the k nearest neighbours of every point (itself excluded), as
// n × k row-major indices (fewer per row only when n ≤ k).
std::vector<uint32_t> NearestNeighbors(const std::vector<Eigen::Vector3d>& points,
                                       const mesh_internal::PointIndex& index, int k) {
  const size_t n = points.size();
  const int kk = static_cast<int>(std::min<size_t>(k, n - 1));
  std::vector<uint32_t> knn(n * kk);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      index.Nearest(points[i], kk + 1, &idx, &d2);
      int out = 0;
      for (size_t j = 0; j < idx.size() && out < kk; ++j) {
        if (idx[j] != i) knn[i * kk + out++] = idx[j];
      }
      while (out < kk) knn[i * kk + out++] = static_cast<uint32_t>(i);
    }
  });
  return knn;
}

KnnGraph SymmetricGraph(const std::vector<uint32_t>& knn, size_t n) {
  const size_t k = knn.size() / n;
  KnnGraph g;
  g.offset.assign(n + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < k; ++j) {
      ++g.offset[i + 1];
      ++g.offset[knn[i * k + j] + 1];
    }
  }
  for (size_t i = 0; i < n; ++i) g.offset[i + 1] += g.offset[i];
  g.adj.resize(g.offset[n]);
  std::vector<uint32_t> fill(g.offset.begin(), g.offset.end() - 1);
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < k; ++j) {
      const uint32_t o = knn[i * k + j];
      g.adj[fill[i]++] = o;
      g.adj[fill[o]++] = static_cast<uint32_t>(i);
    }
  }
  return g;
}

// Unit normals of the least-variance direction of each point's neighbours.
std::vector<Eigen::Vector3d> PcaNormals(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<uint32_t>& knn) {
  const size_t n = points.size();
  const size_t k = knn.size() / n;
  std::vector<Eigen::Vector3d> normals(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      Eigen::Vector3d mean = points[i];
      for (size_t j = 0; j < k; ++j) mean += points[knn[i * k + j]];
      mean /= static_cast<double>(k + 1);
      Eigen::Matrix3d cov = (points[i] - mean) * (points[i] - mean).transpose();
      for (size_t j = 0; j < k; ++j) {
        const Eigen::Vector3d d = points[knn[i * k + j]] - mean;
        cov += d * d.transpose();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
      normals[i] = eig.eigenvectors().col(0).normalized();
    }
  });
  return normals;
}

// Flips normals so that neighbours along a minimum spanning tree agree;
// returns the component id of every point.
absl::StatusOr<std::vector<int>> PropagateOrientation(const KnnGraph& g,
                                                      std::vector<Eigen::Vector3d>* normals,
                                                      const RunContext& ctx) {
  const size_t n = normals->size();
  std::vector<int> component(n, -1);
  using Item = std::tuple<double, uint32_t, uint32_t>;  // weight, to, from
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  int components = 0;
  size_t done = 0;
  for (size_t root = 0; root < n; ++root) {
    if (component[root] >= 0) continue;
    heap.emplace(0.0, static_cast<uint32_t>(root), static_cast<uint32_t>(root));
    while (!heap.empty()) {
      const auto [w, to, from] = heap.top();
      heap.pop();
      if (component[to] >= 0) continue;
      component[to] = components;
      Eigen::Vector3d& nt = (*normals)[to];
      if (nt.dot((*normals)[from]) < 0) nt = -nt;
      if (++done % 65536 == 0) MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
      for (uint32_t e = g.offset[to]; e < g.offset[to + 1]; ++e) {
        const uint32_t o = g.adj[e];
        if (component[o] < 0) heap.emplace(1.0 - std::abs(nt.dot((*normals)[o])), o, to);
      }
    }
    ++components;
  }
  return component;
}

// Fraction of neighbour pairs with clearly (|cos| > 0.5) opposite normals.
double DisagreeingFraction(const std::vector<uint32_t>& knn,
                           const std::vector<Eigen::Vector3d>& normals) {
  const size_t k = knn.size() / normals.size();
  int64_t confident = 0;
  int64_t opposite = 0;
  for (size_t i = 0; i < normals.size(); ++i) {
    for (size_t j = 0; j < k; ++j) {
      const double c = normals[i].dot(normals[knn[i * k + j]]);
      if (std::abs(c) <= 0.5) continue;
      ++confident;
      if (c < 0) ++opposite;
    }
  }
  return confident == 0 ? 0.0 : static_cast<double>(opposite) / confident;
}

// Flips the normals of every component whose divergence sum says outward;
// returns whether any was flipped.
bool TurnInward(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& component,
                std::vector<Eigen::Vector3d>* normals) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const int count = *std::max_element(component.begin(), component.end()) + 1;
  std::vector<double> outwardness(count, 0.0);
  for (size_t i = 0; i < points.size(); ++i) {
    outwardness[component[i]] += (points[i] - centroid).dot((*normals)[i]);
  }
  bool flipped = false;
  for (size_t i = 0; i < points.size(); ++i) {
    if (outwardness[component[i]] > 0) {
      (*normals)[i] = -(*normals)[i];
      flipped = true;
    }
  }
  return flipped;
}

}  // namespace

absl::StatusOr<OrientedNormals> InwardNormals(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<Eigen::Vector3d>& given,
                                              const mesh_internal::PointIndex& index, int k,
                                              const RunContext& ctx) {
  constexpr double kMaxDisagreeing = 0.1;
  const std::vector<uint32_t> knn = NearestNeighbors(points, index, k);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  OrientedNormals out;
  if (!given.empty()) {
    out.normals.resize(given.size());
    for (size_t i = 0; i < given.size(); ++i) out.normals[i] = given[i].normalized();
    if (DisagreeingFraction(knn, out.normals) <= kMaxDisagreeing) {
      out.flipped = TurnInward(points, std::vector<int>(points.size(), 0), &out.normals);
      return out;
    }
    out.flipped = true;
  } else {
    out.normals = PcaNormals(points, knn);
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  const KnnGraph graph = SymmetricGraph(knn, points.size());
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> component,
                           PropagateOrientation(graph, &out.normals, ctx));
  out.flipped = TurnInward(points, component, &out.normals) || out.flipped;
  return out;
}

}  // namespace meshseg::reconstruct_internal
