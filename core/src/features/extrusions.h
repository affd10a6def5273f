// Seed 002 D2: linear extrusions. For each candidate direction d (cylinder
// axes, and the common perpendicular of adjacent planes), the planes with
// normal ⟂ d and cylinders with axis ∥ d form connected groups; a group of
// at least three regions with three or more planes (their normals then lie
// in one plane) or two or more cylinders is an extrusion along d, provided
// its other neighbours are caps (planes ⟂ d) — this leaves out the slabs of
// a prism cut along directions that are not its extrusion direction.
#ifndef MESHSEG_SRC_FEATURES_EXTRUSIONS_H_
#define MESHSEG_SRC_FEATURES_EXTRUSIONS_H_

#include <span>
#include <vector>

#include "features/feature_geometry.h"
#include "meshseg/features.h"

namespace meshseg::features_internal {

// Returns the linear extrusions, each member set once.
std::vector<Feature> FindExtrusions(const Topology& topology, std::span<const Region> regions,
                                    const RegionGraph& graph, const Tolerances& tol);

}  // namespace meshseg::features_internal

#endif  // MESHSEG_SRC_FEATURES_EXTRUSIONS_H_
