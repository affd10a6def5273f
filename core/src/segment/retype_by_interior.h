// Type decision on a region's interior (our addition to ALGORITHMS.md S1
// and S2).
// A region's outer row of vertices sits on the crease it shares with its
// neighbour, which the mesh rounds off (marching cubes blurs it over a
// voxel) and where n'_i turns toward the neighbour. On a narrow band between
// two such creases those rows decide the type: a 45-degree chamfer band
// 6 h wide at sigma = 0.15 h fits a sphere (rms 1.06 sigma) better than
// a cone (1.11 sigma) over all its vertices, and the alpha test, which
// passes the sphere first, agrees. Without the outer row the cone fits at
// the noise (0.98 sigma) and the sphere does not (1.02 sigma).
#ifndef MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_
#define MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_

#include <cstddef>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Below this many interior vertices a region keeps its type.
inline constexpr std::size_t kMinInteriorVertices = 30;

// The vertices (of `vertices`) whose every neighbour is labelled with one
// of `ids`.
std::vector<int> InteriorVertices(const SegmentContext& c, const std::vector<int>& labels,
                                  std::span<const int> ids, std::span<const int> vertices);

// True if region `id` (`r`) has kMinInteriorVertices interior vertices
// and its type does not fit them at the noise (FitsAtNoise): the gate of
// the step that takes a region apart (SplitOffPlanes).
bool TypeMissesInterior(const SegmentContext& c, const std::vector<int>& labels, int id,
                        const RegionState& r);

// Gives every cylinder, sphere, cone or torus region the curved type that
// explains its interior vertices best (InformationScore), if that scores
// kScoreMargin less than its own type, or that type's simplest limit doing
// as well; or, before that, the simplest limit of its own type (a cone or
// cylinder for a torus, a cylinder for a cone) that fits at the noise and
// scores within kScoreMargin of the best, or that is within half a sigma of
// the noise and scores less than kScoreMargin above its own type (whose
// extra parameters must buy that much). Only if some type fits the
// interior at the noise (FitsAtNoise), or near it (within a sigma) and
// either at half the own type's model error or less (a torus on a
// countersink, 3.26 sigma off where the cone is 0.28) or, within half a
// sigma, scoring kScoreMargin below it (a sphere on a chamfer, 0.49 sigma,
// the cone 0.26) or, for a limit of its own type, less than kScoreMargin
// above it: on a noise-free or remeshed CAD mesh the residuals are the
// meshing's, which a type with more parameters follows better (the
// countersinks of a remeshed CAD part would become tori), and on a mixed
// region the scores of misfits say nothing.
// A cone region's own score is that of the better of its free cone and
// the cone on the axis of a cylinder or cone beside it (BestCoaxialCone,
// retype_coaxial_bands.h; a countersink or chamfer shares its bore's or
// shaft's axis by design): on a narrow band at the noise a sphere, with 2
// parameters fewer than a free cone, scores below it by chance (on a
// countersink band a quarter coarser than the part's voxels at 0.15 h:
// sphere 15 below the free cone, and 3.7 above the cone on the bore's
// axis), and the evidence for a change of type must beat the cone the
// region can be.
// On a mesh whose vertices lie on facets (SegmentParams::on_facets) no type
// fits at the noise; there the type of lowest score over all of the
// region's vertices takes over if it scores kScoreMargin below its own, or
// its simplest limit within kScoreMargin of it.
// The new surface is fitted to the whole region. Returns the ids retyped.
std::vector<int> RetypeByInterior(const SegmentContext& c, const std::vector<int>& labels,
                                  std::vector<RegionState>* regions);

// RetypeByInterior, then, if it retyped a region, the expansion with
// re-estimation (ExpandRegions, alpha_expansion.h). The retype is a rule,
// not a move E priced: the region keeps the rows its old surface bent to
// take (a sphere follows a chamfer's rounded crease rows, which lie off the
// cone), and on those rows E charges the new surface for them. Priced from
// that labelling, the old type comes back as a gain (RetypeIfLower) that the
// labelling the expansion places for the new type refutes; PEARL follows a
// change of model by the labelling step before any move compares models.
// Returns the ids retyped. Errors: CANCELLED on stop.
absl::StatusOr<std::vector<int>> RetypeByInteriorAndExpand(const SegmentContext& c,
                                                           std::vector<int>* labels,
                                                           std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_
