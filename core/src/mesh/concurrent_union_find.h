// Disjoint sets over the integers 0..n-1 joined side by side: a concurrent
// union-find whose roots are the lowest elements of their sets.
#ifndef MESHSEG_MESH_CONCURRENT_UNION_FIND_H_
#define MESHSEG_MESH_CONCURRENT_UNION_FIND_H_

#include <atomic>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::mesh_internal {

// Joins only hang a root under a smaller root, so a tree's root is its
// smallest element whatever order the joins run in: numbering the roots in
// index order numbers the sets as a search seeded in index order does.

// n sets of one element each (every element its own root), set side by side.
inline std::vector<std::atomic<int>> SingletonSets(int n) {
  std::vector<std::atomic<int>> parent(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i < r.end(); ++i) parent[i].store(i, std::memory_order_relaxed);
  });
  return parent;
}

// Root of a's tree; the walk halves the path it takes (each element it
// passes then points at an ancestor, still in the same tree).
inline int FindLowestRoot(std::vector<std::atomic<int>>& parent, int a) {
  while (true) {
    const int p = parent[a].load(std::memory_order_relaxed);
    if (p == a) return a;
    const int up = parent[p].load(std::memory_order_relaxed);
    if (up != p) parent[a].store(up, std::memory_order_relaxed);
    a = up;
  }
}

// Joins the trees of a and b: the larger root goes under the smaller
// (retried if another join moved it first).
inline void JoinToLowest(std::vector<std::atomic<int>>& parent, int a, int b) {
  while (true) {
    a = FindLowestRoot(parent, a);
    b = FindLowestRoot(parent, b);
    if (a == b) return;
    if (a > b) std::swap(a, b);
    int expected = b;
    if (parent[b].compare_exchange_strong(expected, a)) return;
  }
}

// After the joins: the set number of every element `kept(i)` accepts, -1 for
// the others. The roots are numbered in index order, serially, each by
// `number(root)` (the number is stored in the root's parent entry, which the
// joins no longer need), so the sets are numbered as a search seeded in
// index order numbers them; then every element takes its root's number.
template <typename Kept, typename Number>
std::vector<int> NumberSets(std::vector<std::atomic<int>>& parent, Kept kept, Number number) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> set(n, -1);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i < r.end(); ++i) {
      if (kept(i)) set[i] = FindLowestRoot(parent, i);
    }
  });
  for (int i = 0; i < n; ++i) {
    if (set[i] == i) parent[i].store(number(i), std::memory_order_relaxed);
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i < r.end(); ++i) {
      if (set[i] >= 0) set[i] = parent[set[i]].load(std::memory_order_relaxed);
    }
  });
  return set;
}

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_CONCURRENT_UNION_FIND_H_
