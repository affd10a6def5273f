// Outer, inner or around-the-axis: a loop that winds once around the axis of
// a cylinder, cone or torus region is axial (a cylinder through a hole has
// two and no outer loop); of the other loops of a patch without axial loops,
// the one whose vector area agrees most with the patch's outward normal
// (counterclockwise about it) is the outer loop, the rest are holes.
#ifndef MESHSEG_SRC_TOPOLOGY_CLASSIFY_LOOPS_H_
#define MESHSEG_SRC_TOPOLOGY_CLASSIFY_LOOPS_H_

#include <span>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "topology/trace_loops.h"

namespace meshseg::topology_internal {

// Sets the kind of every loop in `traced`.
void ClassifyLoops(const TriMesh& mesh, std::span<const int> face_labels,
                   std::span<const Region> regions, TracedLoops* traced);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_CLASSIFY_LOOPS_H_
