#include "reconstruct/octree.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>

#include "absl/container/flat_hash_set.h"
#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: octree";
constexpr int kBits = 20;
constexpr uint64_t kMask = (uint64_t{1} << kBits) - 1;

// A cell at one level: its integer coordinates packed into one key.
uint64_t Key(uint64_t x, uint64_t y, uint64_t z) { return (x << (2 * kBits)) | (y << kBits) | z; }
std::array<int64_t, 3> Coords(uint64_t key) {
  return {static_cast<int64_t>(key >> (2 * kBits)), static_cast<int64_t>((key >> kBits) & kMask),
          static_cast<int64_t>(key & kMask)};
}
uint64_t Parent(uint64_t key) {
  const auto c = Coords(key);
  return Key(c[0] >> 1, c[1] >> 1, c[2] >> 1);
}

}  // namespace

absl::StatusOr<std::vector<OctreeLeaf>> BalancedOctreeLeaves(
    const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& origin, double size,
    int max_level, const RunContext& ctx) {
  assert(max_level >= 1 && max_level <= kMaxOctreeLevel && "octree level out of range");
  // internal[l]: cells of level l that are subdivided.
  std::vector<absl::flat_hash_set<uint64_t>> internal(max_level);
  const int64_t cells = int64_t{1} << max_level;
  for (const auto& p : points) {
    std::array<uint64_t, 3> c;
    for (int a = 0; a < 3; ++a) {
      const int64_t i = static_cast<int64_t>((p[a] - origin[a]) / size * cells);
      c[a] = static_cast<uint64_t>(std::clamp<int64_t>(i, 0, cells - 1));
    }
    internal[max_level - 1].insert(Key(c[0] >> 1, c[1] >> 1, c[2] >> 1));
  }
  // Deepest first: a subdivided cell needs all its same-level neighbours to
  // exist, so their parents are subdivided too (2:1 balance without ripples).
  for (int l = max_level - 1; l >= 1; --l) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    const int64_t n = int64_t{1} << l;
    for (const uint64_t key : internal[l]) {
      const auto c = Coords(key);
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= 1; ++dz) {
            const int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
            if (x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n) continue;
            internal[l - 1].insert(Parent(Key(x, y, z)));
          }
        }
      }
    }
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  std::vector<std::pair<int, uint64_t>> leaf_keys;
  for (int l = 0; l < max_level; ++l) {
    for (const uint64_t key : internal[l]) {
      const auto c = Coords(key);
      for (int child = 0; child < 8; ++child) {
        const uint64_t k = Key(2 * c[0] + (child & 1), 2 * c[1] + ((child >> 1) & 1),
                               2 * c[2] + ((child >> 2) & 1));
        if (l + 1 == max_level || !internal[l + 1].contains(k)) leaf_keys.emplace_back(l + 1, k);
      }
    }
  }
  std::sort(leaf_keys.begin(), leaf_keys.end());
  std::vector<OctreeLeaf> leaves;
  leaves.reserve(leaf_keys.size());
  for (const auto& [level, key] : leaf_keys) {
    const double cell = size / static_cast<double>(int64_t{1} << level);
    const auto c = Coords(key);
    const Eigen::Vector3d corner(c[0], c[1], c[2]);
    leaves.push_back({origin + (corner.array() + 0.5).matrix() * cell, cell, level});
  }
  return leaves;
}

}  // namespace meshseg::reconstruct_internal
