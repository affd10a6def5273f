// Segmentation of exact tessellations (CAD exports: STL / OBJ whose
// vertices a modeller computed on the B-rep's surfaces), facet by facet.
//
// One criterion decides membership: a facet lies on a surface iff its
// corners lie on it to the rounding of the file's numbers and its plane is
// a chord plane of the surface over it (facet_on_surface.h). Candidate
// surfaces (hypotheses) are fitted exactly to small facet groups, plane
// first, then cylinder, cone, sphere, torus (exact_hypotheses.h), and grown
// over every facet that meets the criterion. A facet may meet several (a
// strip of a cylinder lies in its own plane; the corners of a slot's flat
// side and of its rounds' last facets lie on one circle): each facet goes to
// the hypothesis that explains the most corners of what is still free, the
// simpler type on a tie (lazy greedy set cover: a surface's claim is
// recounted on the facets the ones before it left, and it takes the
// edge-connected pieces of them that still hold evidence for its type).
// Facets no analytic surface explains form FREEFORM regions, one per piece
// edge-connected over edges no sharper than the tessellation's own angular
// step (the largest dihedral angle inside the curved regions found); a lone
// facet is a plane. Regions lying on one surface (coplanar faces, the
// patches of a chamfer interrupted by flats) share a surface
// (shared_surfaces.h).
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
