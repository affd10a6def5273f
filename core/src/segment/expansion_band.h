// The bands of alpha-expansion (alpha_expansion.h): the vertices not
// labelled alpha within a number of mesh edges (rings) of alpha's
// vertices, found from the boundaries rather than from every vertex of
// alpha.
//
// A vertex is in alpha's first ring iff it is not labelled alpha and a
// neighbour is; such a vertex lies on a boundary (a neighbour has another
// label). The boundary vertices are kept, grouped by the regions whose
// first ring they are in, as of the last Regroup; a vertex that joined a
// first ring since then changed its label, or a neighbour did, so it is
// among the vertices Moved reported since (and their neighbours). Ring k
// is the set of vertices at graph distance k from alpha's vertices (a
// shortest path enters no vertex of alpha after its start), whatever the
// order the first ring is found in, and the band is returned sorted: the
// same band as walking out from every vertex of alpha, in the work of
// alpha's boundary.
#ifndef MESHSEG_SRC_SEGMENT_EXPANSION_BAND_H_
#define MESHSEG_SRC_SEGMENT_EXPANSION_BAND_H_

#include <cstdint>
#include <span>
#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

class ExpansionBands {
 public:
  // The boundaries of `labels` (region ids below `region_count`, or -1).
  ExpansionBands(const SegmentContext& c, const std::vector<int>& labels, int region_count);

  // The vertices not labelled `alpha` within `rings` mesh edges of a vertex
  // labelled `alpha`, sorted; each numbered by its place in Node() until
  // Release.
  std::vector<int> Band(const std::vector<int>& labels, int alpha, int rings);
  // Band vertex v's place in the band (-1: v is not in the band held).
  int Node(int v) const { return node_[v]; }
  // Clears the numbering of `band` (as Band returned it).
  void Release(std::span<const int> band);

  // The labels of `vertices` changed since the last Regroup.
  void Moved(std::span<const int> vertices);
  // Groups the boundary vertices of `labels` by region again (cheaper
  // bands while many vertices were Moved).
  void Regroup(const std::vector<int>& labels);

 private:
  bool OnBoundary(const std::vector<int>& labels, int v) const;
  void Touch(int v);

  const SegmentContext& c_;
  std::vector<int> node_;          // per vertex: band place, 0 while walked, -1
  std::vector<int> boundary_;      // the boundary vertices at the last Regroup
  std::vector<uint8_t> listed_;    // per vertex: in boundary_
  std::vector<int> touched_;       // Moved vertices and their neighbours
  std::vector<uint8_t> touched_flag_;
  std::vector<std::vector<int>> first_ring_;  // per region, of boundary_
};

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXPANSION_BAND_H_
