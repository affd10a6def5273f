// A band on the axis of a turned face beside it (our addition to
// ALGORITHMS.md S1 and S2). A countersink or a chamfer shares its bore's or
// shaft's axis by design; fitted alone, a narrow band at sigma = 0.15 h can
// take a torus that beats the cone it is by bending its axis and its profile
// into the noise (on a 45-degree countersink band between r 8 and 12: the
// torus R 25.6, r 22.3, 19 below the cone on the interior). On the axis of
// the face beside it the cone has 2 free parameters, not 6.
#ifndef MESHSEG_SRC_SEGMENT_RETYPE_COAXIAL_BANDS_H_
#define MESHSEG_SRC_SEGMENT_RETYPE_COAXIAL_BANDS_H_

#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// For every sphere or torus region with kMinInteriorVertices interior
// vertices and a cylinder or cone neighbour on its axis (a torus: axes
// within kCoaxialMaxAngleDeg, and the neighbour's passing within
// kCoaxialMaxOffset of the tube radius of its centre; a sphere: within that
// share of its radius of its centre), fits a cone to the interior together
// with the neighbour's vertices on one axis (FitCoaxial), and scores it on
// the interior with kCoaxialConeParameters (InformationScore). The best
// scoring such cone is proposed, and the region becomes it iff that lowers E
// (RetypeDelta's terms with that surface, against the region re-estimated
// with its own type), its label counting kCoaxialConeParameters: the axis
// is the neighbour's (energy.h, "Shared parameters"). Nothing is proposed
// when the estimated noise is zero. Returns the ids of the regions retyped.
inline constexpr int kCoaxialConeParameters = 2;  // apex along the axis, half angle
inline constexpr int kCoaxialSphereParameters = 2;  // centre along the axis, radius

// Region `r` as the cone `cone` fitted on a turned neighbour's axis: its
// label counts kCoaxialConeParameters (shared_parameters the other 4).
RegionState CoaxialConeRegion(const RegionState& r, const Surface& cone);

std::vector<int> RetypeCoaxialBands(const SegmentContext& c, const std::vector<int>& labels,
                                    std::vector<RegionState>* regions);

// The same band's two models on the turned face's axis, each priced from
// the labelling placed for it (PEARL compares models only so): on a narrow
// band the outer rows sit on the creases, and on the labels as they stand
// they side with the type they made (a chamfer band grown as a sphere: the
// sphere over all of it below the cone), while on its interior neither
// type need fit at the noise, so that no interior proposal asks. For every
// sphere or torus region with kMinInteriorVertices interior vertices whose
// cone on a turned neighbour's axis (BestCoaxialCone) meets that interior
// near the noise (within kScoredNearError sigmas), the region is made, on
// copies, that cone (CoaxialConeRegion) and, for a sphere not yet on a
// neighbour's axis, the sphere on that axis (SphereOnConeAxis), each
// re-estimated and followed by the expansion (ExpandRegions); the one of
// lower E is kept iff E falls. Both are charged only the parameters their
// own vertices estimate (energy.h, "Shared parameters"): weighed against
// the free sphere alone, the cone would win by the 2 parameters of the
// centre's offset from the axis, which a sphere centred on that axis does
// not estimate either (a shallow dome centred on a shaft's axis would
// become a nearly flat cone). Priced at an expansion's fixed point
// (Improve asks it right after RetypeByInterior), so that the expansion
// alone would gain nothing. Nothing is proposed when the estimated noise is
// zero. Returns the ids of the regions changed. Errors: CANCELLED on stop.
absl::StatusOr<std::vector<int>> PlaceCoaxialBands(const SegmentContext& c,
                                                   std::vector<int>* labels,
                                                   std::vector<RegionState>* regions);

// Sphere region `r` refitted with its centre on the axis of `cone` (the
// turned neighbour's, fitted with it), its label counting the 2 parameters
// its vertices estimate (the centre along the axis, the radius): the
// algebraic fit |x - p|^2 = 2 t (x - p).d + (R^2 - t^2), linear in t and
// R^2 - t^2, for the centre p + t d. nullopt for another type or no fit.
std::optional<RegionState> SphereOnConeAxis(const SegmentContext& c, const RegionState& r,
                                            const Surface& cone);

// The cone fitted to `interior` (of region `id`) on the axis of a cylinder
// or cone region beside it whose axis is region `id`'s (as above; for a
// cone band any such neighbour: a narrow band leaves its own axis
// uncertain, and the caller asks the fit to meet it near the noise), with
// its mean squared distance there and InformationScore on
// kCoaxialConeParameters: the lowest scoring over such neighbours, nullopt
// if none.
struct CoaxialFit {
  FitResult fit;
  double mean_square = 0.0;
  double score = 0.0;
};
std::optional<CoaxialFit> BestCoaxialCone(const SegmentContext& c, const std::vector<int>& labels,
                                          const std::vector<RegionState>& regions, int id,
                                          const std::vector<int>& interior);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_RETYPE_COAXIAL_BANDS_H_
