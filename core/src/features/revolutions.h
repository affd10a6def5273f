// Seed 002 D3: surfaces of revolution. For each candidate axis (the axes of
// cylinder, cone and torus regions, largest region first), the members are
// the cylinders, cones and tori on that axis, the spheres centred on it and
// the planes perpendicular to it whose boundary curves are all circles
// centred on it; a connected group of two or more members, not all planes,
// is a surface of revolution.
#ifndef MESHSEG_SRC_FEATURES_REVOLUTIONS_H_
#define MESHSEG_SRC_FEATURES_REVOLUTIONS_H_

#include <span>
#include <vector>

#include "features/feature_geometry.h"
#include "meshseg/features.h"

namespace meshseg::features_internal {

// Returns the surfaces of revolution, each member set once.
std::vector<Feature> FindRevolutions(const Topology& topology, std::span<const Region> regions,
                                     const RegionGraph& graph, const Tolerances& tol);

}  // namespace meshseg::features_internal

#endif  // MESHSEG_SRC_FEATURES_REVOLUTIONS_H_
