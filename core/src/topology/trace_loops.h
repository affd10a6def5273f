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

// The patches of `face_labels` (labels in [-1, region_count)): each labelled
// face's patch index within its region, numbered in order of the patch's
// lowest face, and the patch count per region. It reads only the mesh and
// the labels, so it can be made beside the curves (ExtractTopology does).
struct FacePatches {
  std::vector<int> face_patch;   // per face: patch index within its region, -1 unlabelled
  std::vector<int> patch_count;  // per region
};
FacePatches LabelPatches(const TriMesh& mesh, std::span<const int> face_labels, int region_count);

// Returns the loops of every labelled patch of `patches` (LabelPatches of
// the same labels). `halfedge_curve` is CurveChains::halfedge_curve.
TracedLoops TraceLoops(const TriMesh& mesh, std::span<const int> face_labels,
                       std::span<const int> halfedge_curve, FacePatches patches);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_TRACE_LOOPS_H_
