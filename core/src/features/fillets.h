// Seed 002 D1: fillets recognised from a blend region's surface, its smooth
// (tangent) neighbours and their fitted geometry.
//   FLT1 torus T between sphere S and plane P: n_P ∥ axis_T, centre_S on axis_T.
//   FLT2 torus T between cylinder C and plane P: n_P ∥ axis_T ∥ axis_C (and
//        the axes coincide).
//   FLT3 cylinder C between planes P1, P2: axis_C ⟂ n_P1, n_P2; the angle
//        between the outward normals (the arc turned) in (0°, 180°).
//   FLT4 sphere (all three convex or all concave) or FLT4' torus (mixed)
//        smoothly joining three FLT3 fillets.
#ifndef MESHSEG_SRC_FEATURES_FILLETS_H_
#define MESHSEG_SRC_FEATURES_FILLETS_H_

#include <span>
#include <vector>

#include "features/feature_geometry.h"
#include "meshseg/features.h"

namespace meshseg::features_internal {

// Returns the FLT1, FLT2 and FLT3 fillets, one per blend region, ascending.
std::vector<Feature> FindEdgeFillets(const Topology& topology, std::span<const Region> regions,
                                     const RegionGraph& graph, const Tolerances& tol);

// Returns the FLT4 / FLT4' corner blends among the FLT3 fillets of `fillets`.
std::vector<Feature> FindCornerBlends(const Topology& topology, std::span<const Region> regions,
                                      const RegionGraph& graph,
                                      std::span<const Feature> fillets);

}  // namespace meshseg::features_internal

#endif  // MESHSEG_SRC_FEATURES_FILLETS_H_
