// The edge heap of the quadric collapse loop (edge_collapse.cc): a min-heap
// of (cost, halfedge) entries laid out for the cache, with lazy deletion
// (stale entries are skipped when popped or purged in bulk).
#ifndef MESHSEG_VOXEL_ENTRY_HEAP_H_
#define MESHSEG_VOXEL_ENTRY_HEAP_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace meshseg::voxel_internal {

struct Entry {
  float cost;
  int halfedge;  // v0 = from (removed), v1 = to (kept)
  bool operator==(const Entry&) const = default;
};

// An 8-ary min-heap of 8-byte entries: a node's eight children fill one
// 64-byte cache line (the storage is offset so that they start on one), so
// a pop from a heap of millions touches half the lines a 4-ary heap of
// 16-byte entries would.
// No entry: an edge with no live heap entry.
constexpr Entry kNoEntry{0.0f, -1};

class EntryHeap {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  const Entry& top() const { return At(0); }
  void Reserve(size_t n) {
    storage_.reserve(n + kLine);
    Align();
  }
  // Replaces the contents by `entries` in heap order (bottom-up, linear).
  void Assign(std::span<const Entry> entries) {
    storage_.resize(entries.size() + kLine);
    Align();
    size_ = entries.size();
    std::copy(entries.begin(), entries.end(), &At(0));
    for (size_t i = size_; i-- > 0;) SiftDown(i, At(i));
  }
  // Drops the entries `stale` says are stale and rebuilds the heap order.
  template <typename Stale>
  void Purge(Stale stale) {
    Entry* first = &At(0);
    size_ = std::remove_if(first, first + size_, stale) - first;
    for (size_t i = size_; i-- > 0;) SiftDown(i, At(i));
  }
  void Push(const Entry& e) {
    if (offset_ + size_ + 1 > storage_.size()) {
      const std::vector<Entry> items(&At(0), &At(0) + size_);
      storage_.resize(2 * storage_.size() + kLine);
      Align();
      std::copy(items.begin(), items.end(), &At(0));
    }
    size_t i = size_++;
    while (i > 0) {
      const size_t parent = (i - 1) / kArity;
      if (!(e.cost < At(parent).cost)) break;
      At(i) = At(parent);
      i = parent;
    }
    At(i) = e;
  }
  void Pop() {
    const Entry last = At(--size_);
    if (size_ > 0) SiftDown(0, last);
  }

 private:
  static constexpr size_t kArity = 8;
  static constexpr size_t kLine = 64 / sizeof(Entry);

  Entry& At(size_t i) { return storage_[offset_ + i]; }
  const Entry& At(size_t i) const { return storage_[offset_ + i]; }
  // Children of i are kArity * i + 1 ...: slot 1 starts a cache line.
  void Align() {
    const auto address = reinterpret_cast<uintptr_t>(storage_.data());
    offset_ = (kLine - 1 + kLine - (address / sizeof(Entry)) % kLine) % kLine;
  }
  // Places e at or below slot i.
  void SiftDown(size_t i, const Entry e) {
    while (true) {
      const size_t first = kArity * i + 1;
      if (first >= size_) break;
      size_t best = first;
      const size_t end = std::min(first + kArity, size_);
      for (size_t c = first + 1; c < end; ++c) {
        if (At(c).cost < At(best).cost) best = c;
      }
      if (!(At(best).cost < e.cost)) break;
      At(i) = At(best);
      i = best;
    }
    At(i) = e;
  }

  std::vector<Entry> storage_;
  size_t offset_ = 0;
  size_t size_ = 0;
};

}  // namespace meshseg::voxel_internal

#endif  // MESHSEG_VOXEL_ENTRY_HEAP_H_
