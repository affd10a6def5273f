// The type decisions of ALGORITHMS.md S1 step 2.5 asked again of regions
// that absorption, merging and refinement changed: general quadrics, planes
// their plane no longer fits, curved regions their type misses.
#ifndef MESHSEG_SRC_SEGMENT_RETYPE_REGIONS_H_
#define MESHSEG_SRC_SEGMENT_RETYPE_REGIONS_H_

#include <span>
#include <vector>

#include "segment/kept_prices.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

inline constexpr std::size_t kMinRetypeVertices = 10;

// Gives general-quadric regions the first analytic type passing the alpha
// test on their non-sharp vertices (regions change after absorption and
// merging, so ALGORITHMS.md S1 step 2.5 is asked again).
void RetypeQuadrics(const SegmentContext& c, std::vector<RegionState>* regions);

// Gives region `r` the one of `types` that lowers E most, with the surface
// of that type fitted to it for least energy (FitForEnergy), if it lowers E
// (RetypeDelta, energy.h) against `r` re-estimated with its own type (a
// region keeps the surface it grew with until a refit, and priced with that
// stale surface any retype looks a gain). Returns whether it did.
bool RetypeIfLower(const SegmentContext& c, RegionState* r, std::span<const SurfaceType> types);

// Proposes for every plane region that its plane no longer fits (the alpha
// test fails on its non-sharp vertices) the curved type DecideCurvedType
// finds there, taken iff it lowers E (RetypeIfLower): at high noise a fillet
// can start as a plane from a seed on its middle and take its whole arc as
// leftovers. Returns the ids of those retyped. With `kept`, a region asked
// before and unchanged since is not asked again (KeptPrices::Refused).
std::vector<int> RetypeBentPlanes(const SegmentContext& c, std::vector<RegionState>* regions,
                                  KeptPrices* kept = nullptr);

// Proposes for region `id` the curved type DecideCurvedType finds on its
// non-sharp vertices (not a general quadric), taken iff it lowers E
// (RetypeIfLower, the re-estimation `kept`'s if given); returns whether it
// was.
bool RetypeCurved(const SegmentContext& c, std::vector<RegionState>* regions, int id,
                  KeptPrices* kept = nullptr);

// Proposes for a curved region whose fit misses it by more than
// kInaccurateError noise sigmas beyond the noise (ModelError), or that its
// type no longer fits validly, the plane and the curved type DecideCurvedType
// finds on its non-sharp vertices; the one that lowers E more is taken, iff
// it lowers E (RetypeDelta against the region re-estimated). A seed on a
// noisy cone can grow as a sphere that passes the tolerances (a 45-degree
// cone joining coaxial cylinders of radius 12 and 8, at sigma = 0.15 h: a
// sphere of r 14.7, model error 1.0 sigma, where the cone's is 0); a torus
// typed on a ring at the rim of a plane annulus (the flat top of a turned
// cylinder with a convex edge round) can be grown over the whole top, where
// only a spindle torus with its cusp inside fits. Returns the ids retyped.
// `kept` as for RetypeBentPlanes.
std::vector<int> RetypeInaccurateCurved(const SegmentContext& c,
                                        std::vector<RegionState>* regions,
                                        KeptPrices* kept = nullptr);

// Proposes for every curved region the plane, and for a cone also the
// cylinder (its limit of half-angle 0, IsLimitOf), the one that lowers E
// more taken iff it lowers E (RetypeIfLower): a curved fit that bends or
// widens less than the noise over its region buys less with its extra
// parameters than the label cost charges for them (a reconstructed flat
// face fitted by a cylinder of radius 914 mm; a CAD edge round fitted by a
// cone of half angle 0.06 degrees, 0.16 wider at one end of 150). Returns
// how many were retyped. `kept` as for RetypeBentPlanes.
int RetypeToSimplerLimits(const SegmentContext& c, std::vector<RegionState>* regions,
                          KeptPrices* kept = nullptr);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_RETYPE_REGIONS_H_
