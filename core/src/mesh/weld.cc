#include "mesh/weld.h"

#include <array>
#include <cstdint>
#include <cstring>

#include "absl/container/flat_hash_map.h"

namespace meshseg::mesh_internal {
namespace {

using Key = std::array<uint64_t, 3>;

Key BitsOf(const Eigen::Vector3d& p) {
  Key key;
  for (int i = 0; i < 3; ++i) {
    const double c = p[i] + 0.0;  // maps -0.0 to 0.0
    std::memcpy(&key[i], &c, sizeof(c));
  }
  return key;
}

}  // namespace

std::vector<int> WeldIdentical(const std::vector<Eigen::Vector3d>& corners,
                               std::vector<Eigen::Vector3d>* vertices) {
  vertices->clear();
  std::vector<int> index(corners.size());
  absl::flat_hash_map<Key, int> first;
  // A closed triangle mesh has about half as many vertices as triangles.
  first.reserve(corners.size() / 5 + 16);
  for (size_t k = 0; k < corners.size(); ++k) {
    const auto [it, inserted] = first.try_emplace(BitsOf(corners[k]),
                                                  static_cast<int>(vertices->size()));
    if (inserted) vertices->push_back(corners[k]);
    index[k] = it->second;
  }
  return index;
}

}  // namespace meshseg::mesh_internal
