#include "reconstruct/cover.h"

#include <cmath>
#include <numeric>
#include <random>

#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: covering";

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
  std::vector<Support> supports;
  std::vector<std::pair<uint32_t, double>> found;
  size_t visited = 0;
  for (const uint32_t i : ShuffledOrder(leaves.size(), seed)) {
    if (++visited % 4096 == 0) {
      MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
      ctx.Progress(kStage, static_cast<double>(visited) / leaves.size());
    }
    if (covered[i]) continue;
    const double diagonal = std::sqrt(3.0) * leaves[i].size;
    const Support s = FitSupport(leaves[i].center, 0.75 * diagonal, in);  // seed 001 §2.1.1
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
  return supports;
}

}  // namespace meshseg::reconstruct_internal
