// Welding of STL corners: corners with bit-identical coordinates become one
// vertex. An open-addressing table over the coordinate bits; no per-corner
// allocation, so 6 M corners weld in a fraction of a second.
#ifndef MESHSEG_MESH_WELD_H_
#define MESHSEG_MESH_WELD_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/large_vector.h"

namespace meshseg::mesh_internal {

// Welds corners given as the bits of their three coordinates (float or double
// bits; -0.0 must already be mapped to 0.0). Insert() returns the vertex index
// of a corner; keys() holds the distinct corners in order of first appearance.
template <typename Bits>
class Welder {
 public:
  using Key = std::array<Bits, 3>;

  explicit Welder(size_t expected_vertices) {
    size_t size = 16;
    while (size < 2 * expected_vertices) size *= 2;
    table_.assign(size, -1);
    keys_.reserve(expected_vertices);
  }

  int Insert(const Key& key) {
    if (2 * (keys_.size() + 1) > table_.size()) Grow();
    size_t slot = Hash(key) & (table_.size() - 1);
    while (true) {
      const int index = table_[slot];
      if (index < 0) {
        table_[slot] = static_cast<int>(keys_.size());
        keys_.push_back(key);
        return table_[slot];
      }
      const Key& found = keys_[index];
      if (found[0] == key[0] && found[1] == key[1] && found[2] == key[2]) return index;
      slot = (slot + 1) & (table_.size() - 1);
    }
  }

  const LargeVector<Key>& keys() const { return keys_; }

 private:
  static uint64_t Hash(const Key& key) {
    uint64_t h = 0x9E3779B97F4A7C15ull;
    for (Bits b : key) {
      h ^= static_cast<uint64_t>(b);
      h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 31;
    }
    return h;
  }

  void Grow() {
    table_.assign(table_.size() * 2, -1);
    for (size_t i = 0; i < keys_.size(); ++i) {
      size_t slot = Hash(keys_[i]) & (table_.size() - 1);
      while (table_[slot] >= 0) slot = (slot + 1) & (table_.size() - 1);
      table_[slot] = static_cast<int>(i);
    }
  }

  LargeVector<int> table_;
  LargeVector<Key> keys_;
};

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_WELD_H_
