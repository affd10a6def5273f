// A renumbering of the vertex graph in which vertices that are close in
// space are close in memory, for the neighbourhood walks of both curvature
// passes and the filter's ring reads. Each walk N(i, W) touches ~100
// vertices within a few edge lengths of v_i; in the order the mesh came in
// (a scan order: rows of a slice, slice after slice) those lie far apart in
// the arrays, and each walk waits on memory. In the Morton (Z-curve) order
// of the vertices' positions a small ball of space maps to a few runs of
// consecutive indices, so consecutive walks share cache lines (Morton 1966;
// the locality argument of space-filling-curve mesh orderings, e.g.
// Isenburg & Lindstrom, "Streaming meshes", IEEE Visualization 2005).
//
// A walk's result does not depend on the numbering: the queue visits the
// same vertices in the same order (each row keeps its order, mapped), so a
// fit over the renumbered neighbourhood sums the same numbers in the same
// order as one over the original, and a filter reads each ring's values in
// the same order.
#ifndef MESHSEG_SRC_CURVATURE_SPATIAL_ORDER_H_
#define MESHSEG_SRC_CURVATURE_SPATIAL_ORDER_H_

#include <span>
#include <vector>

#include <Eigen/Core>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/curvature.h"
#include "meshseg/mesh.h"

namespace meshseg::curvature_internal {

// The graph renumbered: vertex k of `graph` is vertex order[k] of the
// original, rank[v] is the new number of original vertex v.
struct OrderedGraph {
  VertexGraph graph;
  std::vector<int> order;
  std::vector<int> rank;

  // values[order[k]] at k: a per-vertex array in the new numbering
  // (gathered side by side; each entry is a copy).
  template <typename T>
  std::vector<T> Permuted(std::span<const T> values) const {
    std::vector<T> out(order.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size(), 16384),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t k = r.begin(); k < r.end(); ++k) out[k] = values[order[k]];
                      });
    return out;
  }
};

// The vertex graph of `mesh` in which vertex k is mesh vertex order[k] and
// mesh vertex v is rank[v] (empty spans: the mesh's own numbering, which is
// BuildVertexGraph). Each row lists the neighbours in OpenMesh's circulator
// order, renumbered.
VertexGraph NumberedVertexGraph(const TriMesh& mesh, std::span<const int> order,
                                std::span<const int> rank);

// Returns the vertex graph of `mesh` (as BuildVertexGraph) renumbered in the
// Morton order of its positions (ties, in one cell of a 1024^3 grid over
// the bounding box, by vertex index).
OrderedGraph MortonOrderedGraph(const TriMesh& mesh);

}  // namespace meshseg::curvature_internal

#endif  // MESHSEG_SRC_CURVATURE_SPATIAL_ORDER_H_
