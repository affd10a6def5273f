// The exact fit of the exact-facet path: the surface of one type through
// the corners of a group of facets within the tolerance tau (corners on a
// chord of a curved surface left out, fits a proof from the corners
// excludes not run: fit_exclusion.h), and the evidence a group must hold
// before such a fit says anything about it. The hypotheses
// (exact_hypotheses.h) are seeded, verified and grown with these.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_FIT_H_
#define MESHSEG_SRC_SEGMENT_EXACT_FIT_H_

#include <cstddef>
#include <optional>
#include <span>

#include "meshseg/surface.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// The exact fit of `type` to the corners of `facets`: nullopt unless every
// corner lies within `tau` of it.
std::optional<Surface> FitExactly(const FacetMesh& fm, SurfaceType type,
                                  std::span<const int> facets, double tau);

// True if `facets` hold enough evidence for a surface of `type`: a plane
// needs 4 distinct corners (a facet alone fixes its own plane); a curved
// type kMinCurvedFacets facets of distinct normals (three parallel lines lie
// on a cylinder whatever they are, four do not) and as many corners as its
// parameters plus kSpareCorners (ParameterCount, decide_type.h: the p_T of
// the label cost, energy.h).
bool HoldsEvidence(const FacetMesh& fm, SurfaceType type, std::span<const int> facets);
inline constexpr int kMinCurvedFacets = 3;
inline constexpr int kSpareCorners = 3;

// Facet normals closer than this (radians) are one direction.
inline constexpr double kDistinctNormal = 1e-4;

// Seed groups (exact_hypotheses.h) stop growing at this many facets; the
// fit tells the corners of a group this small apart by a scan, a larger
// one's by hashing.
inline constexpr std::size_t kMaxSeedFacets = 48;

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_FIT_H_
