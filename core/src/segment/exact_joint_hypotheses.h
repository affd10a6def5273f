// Hypotheses of the exact-facet path seeded jointly from several groups of
// facets rather than from the facets around one seed (exact_hypotheses.h):
// where each group alone is explained by a simpler surface that says
// nothing of its neighbours, or is too small to fix any surface, while one
// surface explains them together.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_JOINT_HYPOTHESES_H_
#define MESHSEG_SRC_SEGMENT_EXACT_JOINT_HYPOTHESES_H_

#include <vector>

#include "segment/exact_hypotheses.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// Bands of a surface of revolution. A tessellator cuts a torus (or sphere)
// into bands of facets between parallel circles of it, and any two coaxial
// circles lie on one cone (or cylinder): each band alone is an exact cone.
// Three circles lie on a torus whatever they are (the circle through three
// points of the meridian half-plane), so two bands say nothing either; four
// circles, three adjacent bands, lie on one torus only if it is theirs. So
// for every chain of three edge-adjacent, coaxial cylinder or cone
// hypotheses, each with corners off the others' surfaces, a sphere, else a
// torus, is fitted exactly to their union; it is a hypothesis if every
// facet of the union meets the criterion for it (facet_on_surface.h), and
// is then grown like any other. The greedy cover (exact_facets.h) prefers it
// to the bands, as it explains all their corners. Returns the new
// hypotheses.
std::vector<Hypothesis> RevolvedBandHypotheses(const FacetMesh& fm,
                                               const std::vector<Hypothesis>& hypotheses,
                                               double tau);

// Chains of bands tried from one band, at most.
inline constexpr int kMaxBandChains = 8;

// Pieces of one surface apart. A face cut by other features into small
// patches (a chamfer cone interrupted by the flats of a hexagon) leaves
// pieces that no seed explains: each alone spans too little of the surface
// to fix it, though its corners lie on it exactly. Two pieces (edge-connected
// facets no hypothesis took, `pieces`, each sorted) are fitted together by
// each curved type in order of simplicity; a fit that holds evidence for
// its type on their union and has every facet of it on the surface takes
// every other piece whose facets all lie on it too, and is a joint
// hypothesis over them all (Hypothesis::joint), grown like any other. Only pieces of at least
// kMinJointPieceFacets facets are tried, at most kMaxJointPieces of them, largest first.
std::vector<Hypothesis> JointPieceHypotheses(const FacetMesh& fm,
                                             std::vector<std::vector<int>> pieces, double tau);
inline constexpr std::size_t kMinJointPieceFacets = 3;
inline constexpr std::size_t kMaxJointPieces = 64;

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_JOINT_HYPOTHESES_H_
