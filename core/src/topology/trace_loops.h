// The closed cycles of curves around each region patch (a face-connected
// component of one label): the patch's boundary halfedges, each with the
// patch on its left, followed around the patch and grouped by curve.
#ifndef MESHSEG_SRC_TOPOLOGY_TRACE_LOOPS_H_
#define MESHSEG_SRC_TOPOLOGY_TRACE_LOOPS_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/topology.h"

namespace meshseg::topology_internal {

struct TracedLoops {
  std::vector<Loop> loops;  // id, region, patch, curves set; kind not yet
  // Per loop: its mesh vertex ids in order, the first repeated at the end.
  std::vector<std::vector<int>> loop_vertices;
  std::vector<int> face_patch;   // per face: patch index within its region, -1 unlabelled
  std::vector<int> patch_count;  // per region
};

// Returns the loops of every labelled patch. `halfedge_curve` is
// CurveChains::halfedge_curve; labels lie in [-1, region_count).
TracedLoops TraceLoops(const TriMesh& mesh, std::span<const int> face_labels,
                       std::span<const int> halfedge_curve, int region_count);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_TRACE_LOOPS_H_
