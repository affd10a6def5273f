#include "reconstruct/normals.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: normals";

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

// Union-find whose elements carry a parity: whether an element's normal must
// flip to agree with its root's.
class ParityForest {
 public:
  explicit ParityForest(size_t n) : parent_(n), parity_(n, 0), rank_(n, 0) {
    std::iota(parent_.begin(), parent_.end(), 0u);
  }

  // Returns the root of i and sets *parity to i's flip relative to it;
  // points the path at the root.
  uint32_t Find(uint32_t i, uint8_t* parity) {
    uint32_t root = i;
    uint8_t total = 0;
    while (parent_[root] != root) {
      total ^= parity_[root];
      root = parent_[root];
    }
    uint32_t x = i;
    uint8_t px = total;  // x's flip relative to root
    while (x != root && parent_[x] != root) {
      const uint32_t next = parent_[x];
      const uint8_t next_parity = px ^ parity_[x];
      parent_[x] = root;
      parity_[x] = px;
      x = next;
      px = next_parity;
    }
    *parity = total;
    return root;
  }

  // Joins the trees of a and b so that flip(a) ^ flip(b) = `relative`;
  // false if they are one tree already.
  bool Join(uint32_t a, uint32_t b, uint8_t relative) {
    uint8_t pa = 0, pb = 0;
    uint32_t ra = Find(a, &pa), rb = Find(b, &pb);
    if (ra == rb) return false;
    if (rank_[ra] < rank_[rb]) std::swap(ra, rb);
    parent_[rb] = ra;
    parity_[rb] = pa ^ pb ^ relative;
    rank_[ra] += rank_[ra] == rank_[rb];
    return true;
  }

 private:
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> parity_;
  std::vector<uint8_t> rank_;
};

// Flips normals so that neighbours along a minimum spanning tree of the
// symmetric k-NN graph (weight 1 − |n_i·n_j|) agree, the first point of each
// component keeping its sign; returns the component id of every point
// (numbered in the order of their first points). Kruskal's algorithm: the
// edges sorted by weight (in parallel), joined by union-find; it finds the
// tree Prim's propagation from the first point finds (the same minimum
// spanning tree when weights are distinct; with ties, another of equal
// weight), and the flips along a tree do not depend on the order they are
// made in.
absl::StatusOr<std::vector<int>> PropagateOrientation(const std::vector<uint32_t>& knn,
                                                      std::vector<Eigen::Vector3d>* normals,
                                                      const RunContext& ctx) {
  const size_t n = normals->size();
  const size_t k = knn.size() / n;
  const auto& nm = *normals;
  // Edge key: the weight's bits (a non-negative float orders as its bits)
  // above the edge's position i·k + j in `knn`. An edge listed both ways is
  // kept once.
  std::vector<uint64_t> keys;
  keys.reserve(knn.size());
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < k; ++j) {
      const uint32_t o = knn[i * k + j];
      if (o == i) continue;
      if (o < i && std::find(knn.begin() + o * k, knn.begin() + (o + 1) * k, i) !=
                       knn.begin() + (o + 1) * k) {
        continue;
      }
      const float w = static_cast<float>(std::max(0.0, 1.0 - std::abs(nm[i].dot(nm[o]))));
      keys.push_back((uint64_t{std::bit_cast<uint32_t>(w)} << 32) | (i * k + j));
    }
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  tbb::parallel_sort(keys.begin(), keys.end());
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  ParityForest forest(n);
  for (const uint64_t key : keys) {
    const uint32_t e = static_cast<uint32_t>(key);
    const uint32_t i = e / k, o = knn[e];
    forest.Join(i, o, nm[i].dot(nm[o]) < 0);
  }
  std::vector<int> component(n, -1);
  std::vector<int> of_root(n, -1);
  std::vector<uint8_t> root_flip(n, 0);
  int components = 0;
  for (size_t i = 0; i < n; ++i) {
    uint8_t parity = 0;
    const uint32_t root = forest.Find(static_cast<uint32_t>(i), &parity);
    if (of_root[root] < 0) {
      of_root[root] = components++;
      root_flip[root] = parity;
    }
    component[i] = of_root[root];
    if (parity != root_flip[root]) (*normals)[i] = -(*normals)[i];
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
                                              const NeighborTable& nearest, const RunContext& ctx) {
  constexpr double kMaxDisagreeing = 0.1;
  const std::vector<uint32_t>& knn = nearest.index;
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
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> component,
                           PropagateOrientation(knn, &out.normals, ctx));
  out.flipped = TurnInward(points, component, &out.normals) || out.flipped;
  return out;
}

}  // namespace meshseg::reconstruct_internal
