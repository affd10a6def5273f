// Disjoint sets over the integers 0..n-1 as a parent array (parent[i] == i
// for a root): the root of an element, halving the path to it on the way.
#ifndef MESHSEG_MESH_UNION_FIND_H_
#define MESHSEG_MESH_UNION_FIND_H_

#include <vector>

namespace meshseg::mesh_internal {

inline int FindRoot(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_UNION_FIND_H_
