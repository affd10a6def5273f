// The type a region's interior proposes, and the move E makes of it (our
// addition to ALGORITHMS.md S1 and S2).
// A region's outer row of vertices sits on the crease it shares with its
// neighbour, which the mesh rounds off (marching cubes blurs it over a
// voxel) and where n'_i turns toward the neighbour. On a narrow band between
// two such creases those rows decide the type: a 45-degree chamfer band
// 6 h wide at sigma = 0.15 h fits a sphere (rms 1.06 sigma) better than
// a cone (1.11 sigma) over all its vertices, and the alpha test, which
// passes the sphere first, agrees. Without the outer row the cone fits at
// the noise (0.98 sigma) and the sphere does not (1.02 sigma). The interior
// proposes the type; E decides, with the expansion that moves the rows.
#ifndef MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_
#define MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_

#include <cstddef>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "segment/decide_type.h"
#include "segment/kept_prices.h"
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

// True if one of `a` and `b` is a special case of the other: a limit
// (IsLimitOf), or a sphere of a torus (of major radius 0). The general one
// meets whatever the special one meets, so that its fitting too tells
// nothing.
bool Nested(SurfaceType a, SurfaceType b);

// Of `scored` (a region's interior fitted with each curved type), the type
// of lowest score that fits at the noise (FitsAtNoise), is neither `own`
// nor Nested with it (the limits the simplest-limit rule weighs, and the
// generalisations that fit wherever `own` does), and scores less than
// kScoreMargin above `own_score`, if `own` fits at the noise too; else
// nullptr. Two such types the interior cannot tell apart: only the
// labelling each places can (PEARL compares models from labellings placed
// for them), so the other is proposed for E to price.
const ScoredFit* OtherTypeAtTheNoise(const SegmentContext& c, std::span<const ScoredFit> scored,
                                     SurfaceType own, double own_score);

// The retype a region's interior proposes: region `id` as `type`, with
// `surface` fitted to all of its vertices (to the interior if that fit is
// not valid), or a cone on the axis of a turned face beside it
// (BestCoaxialCone), which shares `shared_parameters` with that face
// (RegionState::shared_parameters).
struct InteriorRetype {
  int id = -1;
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
  int shared_parameters = 0;
};

// The proposals, one per cylinder, sphere, cone or torus region at most: the
// curved type that explains its interior vertices best (InformationScore),
// if that scores kScoreMargin less than its own type, or that type's
// simplest limit doing as well; or, before that, the simplest limit of its
// own type (a cone or cylinder for a torus, a cylinder for a cone) that fits
// at the noise and scores within kScoreMargin of the best, or that is within
// half a sigma of the noise and scores less than kScoreMargin above its own
// type (whose extra parameters must buy that much). Only if some type fits
// the interior at the noise (FitsAtNoise), or near it (within a sigma) and
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
// region's vertices is proposed if it scores kScoreMargin below its own, or
// its simplest limit within kScoreMargin of it. Nothing is proposed on a
// noise-free mesh that is not on facets. With `kept`, a region other than
// a cone (whose proposal reads its neighbours) that proposed nothing and is
// unchanged since is not asked again (KeptPrices::Refused).
std::vector<InteriorRetype> ProposeInteriorTypes(const SegmentContext& c,
                                                 const std::vector<int>& labels,
                                                 const std::vector<RegionState>& regions,
                                                 KeptPrices* kept = nullptr);

// The retype by the interior as a move of E (energy.h): each proposal, in
// id order, made together with the expansion it enables, and kept iff E
// falls, E(retype + expansion) < E. The expansion belongs in the price:
// the outer rows that made the region's type are the crease's, and E on the
// labels as they stand sides with the type they made (a chamfer band with
// a row of each neighbour: the sphere over all of it, RetypeDelta to the
// cone > 0). With the proposed type (re-estimated, energy.h Reestimated)
// the rows cost more than on the neighbours' surfaces, the expansion with
// re-estimation hands them over, and the proposed type then meets what is
// left at the noise. Priced at an expansion's fixed point (as Improve asks
// it, first in a round), so that the expansion alone would gain nothing.
// Returns the ids retyped. Errors: CANCELLED on stop.
absl::StatusOr<std::vector<int>> RetypeByInterior(const SegmentContext& c,
                                                  std::vector<int>* labels,
                                                  std::vector<RegionState>* regions,
                                                  KeptPrices* kept = nullptr);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_RETYPE_BY_INTERIOR_H_
