// Segmentation of exact tessellations (CAD exports: STL / OBJ whose
// vertices a modeller computed on the B-rep's surfaces), facet by facet.
//
// The criterion is the segmentation's one energy E (energy.h) with the data
// term of exact vertices: a facet lies on a surface (data cost 0) iff its
// corners lie on it to the rounding of the file's numbers and its plane is
// a chord plane of the surface over it (facet_on_surface.h), else it cannot
// be that surface's (data cost infinite). No noise, so no boundary term and
// no correlation to discount; what remains of E is the label cost of each
// surface, (p_T / 2) ln n over its n corners, the same constants as on a
// noisy mesh, and the outlier cost of corners no surface explains. One
// criterion, two data terms: on a noisy mesh the squared distance in noise
// units, here its limit as the noise goes to 0.
// E is minimised greedily, as uncapacitated facility location is (energy.h):
// candidate surfaces (hypotheses) are fitted exactly to small facet groups,
// plane first, then cylinder, cone, sphere, torus (exact_hypotheses.h), and
// grown over every facet of data cost 0 on them. A facet may lie on several
// (a strip of a cylinder lies in its own plane; the corners of a slot's
// flat side and of its rounds' last facets lie on one circle): the cover
// takes, repeatedly, the hypothesis explaining the most corners of what is
// still free (where a corner's label cost is least, the label cost being
// concave), the simpler type on a tie (a rule: energy.h), recounted lazily
// on the facets the ones before it left, and it takes the edge-connected
// pieces of them that still hold evidence for its type (exact_fit.h:
// HoldsEvidence, a rule: a piece with fewer corners than its type's
// parameters fixes no surface, and the hard data term would give it to any
// surface at no cost). Every hypothesis holding evidence is worth its
// label (its label cost per corner is below the outlier cost). Regions
// lying on one surface (coplanar faces, the patches of a chamfer
// interrupted by flats) are one label of E, joined as the label costs say
// (shared_surfaces.h, energy.h: ExactJoinDelta).
// Facets no analytic surface explains pay the outlier cost and form
// FREEFORM regions, one per piece edge-connected over edges no sharper than
// the tessellation's own angular step (the largest dihedral angle inside
// the curved regions found); a piece whose corners lie on one plane is
// that plane (a label holding evidence the proposals missed), and a lone
// facet a plane too (a rule: its three corners hold no evidence). Two more
// rules remain beside E, each for facets of infinite data cost on every
// hypothesis: a sliver spanning a rim joins the neighbour holding its
// corners, and a gap without a vertex of its own the neighbour whose
// surface holds it within a B-rep edge's tolerance (JoinNeighbours,
// JoinGapPieces in the .cc).
#ifndef MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_
#define MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "meshseg/surface.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

struct ExactRegion {
  SurfaceType type = SurfaceType::kPlane;
  Surface surface;  // in the FacetMesh's frame; a FREEFORM region: a quadric for
                    // display
  std::vector<int> facets;
};

struct ExactFacets {
  std::vector<int> face_labels;  // one per facet, into `regions`
  std::vector<ExactRegion> regions;
  double angular_step = 0.0;  // radians; the freeform smoothness bound used
};

// Without curved regions, the angular step is taken as OpenCASCADE's default
// angular deflection (0.5 rad), the coarsest common exporter setting.
inline constexpr double kDefaultAngularStep = 0.5;

// The edge-connected pieces of `facets` (sorted), each sorted.
std::vector<std::vector<int>> EdgeConnectedPieces(const FacetMesh& fm,
                                                  const std::vector<int>& facets);

// Segments `fm` with tolerance `tau` as above.
// Errors: CANCELLED on stop.
absl::StatusOr<ExactFacets> SegmentFacets(const FacetMesh& fm, double tau, const RunContext& ctx);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_
