#include "reconstruct/cover.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: covering";
// Leaves fitted at once: a 1/kBatchDivisor share of those still uncovered,
// within [kMinBatch, kMaxBatch] (enough to keep every core busy, few enough
// that one support seldom covers another of the same batch).
constexpr size_t kBatchDivisor = 64;
constexpr size_t kMinBatch = 16;
constexpr size_t kMaxBatch = 4096;

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

}  // namespace

absl::StatusOr<std::vector<Support>> CoverBySupports(const std::vector<OctreeLeaf>& leaves,
                                                     const FitInput& in, uint64_t seed,
                                                     const RunContext& ctx) {
  std::vector<Eigen::Vector3d> centers(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) centers[i] = leaves[i].center;
  const mesh_internal::PointIndex leaf_index(centers);
  std::vector<uint8_t> covered(leaves.size(), 0);
  size_t uncovered = leaves.size();
  std::vector<Support> supports;
  std::vector<std::pair<uint32_t, double>> found;
  const std::vector<uint32_t> order = ShuffledOrder(leaves.size(), seed);
  // The greedy covering is sequential, but a leaf's support does not depend
  // on the others: the next `batch` leaves not yet covered are fitted in
  // parallel, then committed in order, skipping those an earlier support of
  // the batch covered (the serial result exactly; the work spent on skipped
  // leaves is the price). The batch is a small fraction of the leaves still
  // uncovered, so few are skipped.
  std::vector<uint32_t> batch;
  std::vector<Support> fitted;
  size_t next = 0;
  while (next < order.size()) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    ctx.Progress(kStage, static_cast<double>(next) / static_cast<double>(order.size()));
    const size_t size = std::clamp<size_t>(uncovered / kBatchDivisor, kMinBatch, kMaxBatch);
    batch.clear();
    for (; next < order.size() && batch.size() < size; ++next) {
      if (!covered[order[next]]) batch.push_back(order[next]);
    }
    fitted.assign(batch.size(), Support{});
    tbb::parallel_for(size_t{0}, batch.size(), [&](size_t b) {
      const OctreeLeaf& leaf = leaves[batch[b]];
      const double diagonal = std::sqrt(3.0) * leaf.size;
      fitted[b] = FitSupport(leaf.center, 0.75 * diagonal, in);  // seed 001 §2.1.1
    });
    for (size_t b = 0; b < batch.size(); ++b) {
      if (covered[batch[b]]) continue;
      const Support& s = fitted[b];
      // Covered: all 8 corners inside, i.e. the farthest corner is.
      leaf_index.WithinRadius(s.center, s.radius, &found);
      for (const auto& [j, unused] : found) {
        const Eigen::Vector3d far =
            (leaves[j].center - s.center).cwiseAbs().array() + 0.5 * leaves[j].size;
        if (!covered[j] && far.squaredNorm() <= s.radius * s.radius) {
          covered[j] = 1;
          --uncovered;
        }
      }
      if (!covered[batch[b]]) {
        covered[batch[b]] = 1;
        --uncovered;
      }
      supports.push_back(s);
    }
  }
  return supports;
}

}  // namespace meshseg::reconstruct_internal
