// Checks on the triangles of the input before OpenMesh sees them: exact
// duplicates, and non-manifold edges and vertices, which OpenMesh cannot hold
// and so cannot count afterwards.
#ifndef MESHSEG_MESH_INPUT_TOPOLOGY_H_
#define MESHSEG_MESH_INPUT_TOPOLOGY_H_

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/large_vector.h"

namespace meshseg::mesh_internal {

struct TopologyCounts {
  int64_t duplicate_face_count = 0;
  int64_t non_manifold_edge_count = 0;    // edges of > 2 triangles
  int64_t non_manifold_vertex_count = 0;  // vertices whose triangles form > 1 fan
};

// Counts non-manifold edges and vertices over the triangles with keep[t] set
// (duplicates included, as they are in the file), then clears keep[t] for
// every triangle with the same vertex set as an earlier kept one. Triangles
// with keep[t] == 0 on entry are ignored. Indices must be
// in [0, vertex_count) and distinct within a triangle. Deterministic; runs the
// per-vertex work with oneTBB.
TopologyCounts AnalyzeInputTopology(int vertex_count,
                                    const LargeVector<std::array<int, 3>>& triangles,
                                    LargeVector<uint8_t>* keep);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_INPUT_TOPOLOGY_H_
