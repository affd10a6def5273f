// The coarse control mesh: feature edges tagged as creases, then QEM edge
// collapse to a target face count that never collapses across a feature
// line, since a smooth limit surface cannot follow a sharp edge that no
// control edge lies on.
#ifndef MESHSEG_SUBDIV_CONTROL_FROM_MESH_H_
#define MESHSEG_SUBDIV_CONTROL_FROM_MESH_H_

#include <cstdint>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/subdiv.h"
#include "subdiv/feature_lines.h"

namespace meshseg::subdiv_internal {

// Returns `mesh` simplified to about `target_faces` faces by the quadric
// edge collapse of voxel_internal::CollapseEdges (Garland-Heckbert quadrics
// as priority, merged vertices at the quadric's optimum, normal-turn guard).
// The edges of `features` (feature_lines.h) are the feature edges: a vertex
// on one only collapses along its feature line and stays on it; vertices
// where the number of feature edges is not two (junctions, line ends) never
// collapse; open borders stay on themselves. The surviving
// feature edges are the creases; feature junctions (three or more feature
// edges) are the corners. Reports progress as "subdiv" in [0, 0.4].
// Errors: those of CollapseEdges; CANCELLED on stop.
absl::StatusOr<ControlMesh> ControlFromMesh(const TriMesh& mesh, int64_t target_faces,
                                            const FeatureLines& features,
                                            const RunContext& ctx = {});

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_CONTROL_FROM_MESH_H_
