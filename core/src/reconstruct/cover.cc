#include "reconstruct/cover.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: covering";
// A sparse hull ball's point reads its centre's side when the centre lies
// within 60° of the point's inward normal (cover.h): an error of up to 30°
// in that normal leaves the centre on the same side of its tangent plane.
constexpr double kMinInsideCosine = 0.5;
// Uncovered leaves fitted together: enough to keep the cores busy for a few
// milliseconds per round (a fit takes ~0.5 ms at a million points), few
// enough that a batch-mate rarely covers another first.
constexpr size_t kBatch = 16;

// Fisher-Yates with our own index draw, so the order is the same with any
// standard library.
std::vector<uint32_t> ShuffledOrder(size_t n, uint64_t seed) {
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937_64 rng(seed);
  for (size_t i = n; i > 1; --i) {
    const size_t j = rng() % i;
    std::swap(order[i - 1], order[j]);
  }
  return order;
}

// Whether every input point in `s`'s ball sees its centre from inside:
// behind its tangent plane by more than ε and within 60° of its inward
// normal n_p (kMinInsideCosine; cover.h).
bool SeenFromInside(const Support& s, const FitInput& in,
                    std::vector<std::pair<uint32_t, double>>* found) {
  in.index.WithinRadiusUnordered(s.center, s.radius, found);
  if (found->empty()) return false;
  for (const auto& [j, unused] : *found) {
    const Eigen::Vector3d to_centre = s.center - in.points[j];
    const double behind = to_centre.dot(in.normals[j]);
    if (!(behind > in.epsilon && behind >= kMinInsideCosine * to_centre.norm())) return false;
  }
  return true;
}

}  // namespace

absl::StatusOr<std::vector<Support>> CoverBySupports(const std::vector<OctreeLeaf>& leaves,
                                                     const FitInput& in, uint64_t seed,
                                                     const RunContext& ctx) {
  std::vector<Eigen::Vector3d> centers(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) centers[i] = leaves[i].center;
  const mesh_internal::PointIndex leaf_index(centers);
  const std::vector<uint32_t> order = ShuffledOrder(leaves.size(), seed);
  std::vector<uint8_t> covered(leaves.size(), 0);
  std::vector<Support> supports;
  std::vector<std::pair<uint32_t, double>> found;
  std::vector<uint32_t> batch;
  std::vector<Support> fitted;
  size_t next = 0;
  size_t reported = 0;
  while (next < order.size()) {
    if (next >= reported + 4096) {
      reported = next;
      MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
      ctx.Progress(kStage, static_cast<double>(next) / leaves.size());
    }
    // The next kBatch leaves not yet covered, fitted in parallel (a fit
    // depends on its leaf alone) ...
    batch.clear();
    while (next < order.size() && batch.size() < kBatch) {
      const uint32_t i = order[next++];
      if (!covered[i]) batch.push_back(i);
    }
    fitted.resize(batch.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, batch.size(), 1), [&](const auto& range) {
      for (size_t b = range.begin(); b != range.end(); ++b) {
        const OctreeLeaf& leaf = leaves[batch[b]];
        fitted[b] = FitSupport(leaf.center, 0.75 * std::sqrt(3.0) * leaf.size,
                               in);  // ALGORITHMS.md S3: start at 0.75 × the cell diagonal
      }
    });
    // ... and taken in order, each only if still uncovered: the serial
    // greedy covering exactly (a fit a batch-mate made needless is dropped).
    for (size_t b = 0; b < batch.size(); ++b) {
      const uint32_t i = batch[b];
      if (covered[i]) continue;
      const Support& s = fitted[b];
      // Covered: all 8 corners inside, i.e. the farthest corner is.
      leaf_index.WithinRadiusUnordered(s.center, s.radius, &found);
      for (const auto& [j, unused] : found) {
        const Eigen::Vector3d far =
            (leaves[j].center - s.center).cwiseAbs().array() + 0.5 * leaves[j].size;
        if (far.squaredNorm() <= s.radius * s.radius) covered[j] = 1;
      }
      covered[i] = 1;
      supports.push_back(s);
    }
  }
  return supports;
}

std::vector<Support> InnerSupports(const std::vector<Support>& supports, const FitInput& in,
                                   double spacing) {
  std::vector<Eigen::Vector3d> at;
  for (const Support& s : supports) {
    const double height = s.g(s.center);
    if (!(std::abs(height) < s.radius)) continue;
    // The ball's disc on its plane, sampled at `spacing`, holds about
    // π (r² − g(c)²) / spacing² points; at least a quarter of that (cover.h).
    const double disc = M_PI * (s.radius * s.radius - height * height) / (spacing * spacing);
    if (!(4.0 * s.point_count >= disc)) continue;
    const Eigen::Vector3d foot = s.center - height * s.m;
    if (!((in.points[in.index.Closest(foot)] - s.center).norm() < s.radius)) continue;
    at.push_back(s.center + (s.radius - height) * s.m);
  }
  std::vector<Support> inner(at.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, at.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) inner[i] = FitSupport(at[i], 0.0, in);
  });
  return inner;
}

std::vector<double> CoveringWeights(const std::vector<Support>& covering, const TetMesh& tets,
                                    const PuFunction& f, int sparse_points, const FitInput& in) {
  std::vector<double> weight = RadiiSquared(covering);
  std::vector<std::pair<uint32_t, double>> found;
  for (size_t v = 0; v < tets.support.size(); ++v) {
    const size_t i = tets.support[v];
    if (i >= covering.size() || !tets.on_hull[v]) continue;
    const Support& s = covering[i];
    if (!(f(s.center) > 0)) continue;
    // A fit on fewer points than the sparse count does not read its centre's
    // side (cover.h): the tie outside stands and so does r², unless every
    // point's own normal puts the centre behind its tangent plane.
    if (s.point_count < sparse_points && !SeenFromInside(s, in, &found)) continue;
    weight[i] = 0.0;
  }
  return weight;
}

std::vector<double> TetWeights(const std::vector<Support>& supports,
                               const std::vector<double>& covering_weight) {
  const size_t covering_count = covering_weight.size();
  std::vector<double> weight(supports.size(), -1.0);
  std::vector<Eigen::Vector3d> centers(covering_count);
  double largest = 0.0;
  for (size_t i = 0; i < covering_count; ++i) {
    weight[i] = covering_weight[i];
    centers[i] = supports[i].center;
    largest = std::max(largest, std::sqrt(weight[i]));
  }
  if (covering_count == 0) return weight;
  const mesh_internal::PointIndex index(centers);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(covering_count, supports.size()), [&](const auto& range) {
        std::vector<std::pair<uint32_t, double>> found;
        for (size_t k = range.begin(); k != range.end(); ++k) {
          const Eigen::Vector3d& p = supports[k].center;
          // Not hidden: w ≥ w_i − |p − c_i|² for every covering centre.
          // Hides none: w < w_j + |p − c_j|² for every covering centre. The
          // nearest centre bounds the second, so the search reaches the
          // larger of its bound's root and the largest root of a weight.
          const uint32_t nearest = index.Closest(p);
          const double hi0 = weight[nearest] + (centers[nearest] - p).squaredNorm();
          double lo = 0.0, hi = hi0;
          index.WithinRadiusUnordered(p, std::max(largest, std::sqrt(hi0)), &found);
          for (const auto& [j, d2] : found) {
            lo = std::max(lo, weight[j] - d2);
            hi = std::min(hi, weight[j] + d2);
          }
          if (lo < hi) weight[k] = 0.5 * (lo + hi);
        }
      });
  return weight;
}

}  // namespace meshseg::reconstruct_internal
