// Corners: the curve ends found while chaining, grouped into clusters by
// junction-artifact curves, each cluster placed at the common point of its
// regions' surfaces (SnapCorner) or at its mean vertex.
#ifndef MESHSEG_SRC_TOPOLOGY_PLACE_CORNERS_H_
#define MESHSEG_SRC_TOPOLOGY_PLACE_CORNERS_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "meshseg/topology.h"

namespace meshseg::topology_internal {

// Fills topo->corners (one per corner vertex, in order) from its curves
// (start/end corners and junction_artifact set). `snap_distance` is in model
// units.
void PlaceCorners(const TriMesh& mesh, std::span<const int> face_labels,
                  std::span<const Region> regions, const std::vector<int>& corner_vertices,
                  double snap_distance, Topology* topo);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_PLACE_CORNERS_H_
