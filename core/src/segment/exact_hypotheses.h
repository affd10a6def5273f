// Hypotheses of the exact-facet path: a surface fitted exactly (within the
// tolerance tau, exact_fit.h) to a small group of facets, verified on every
// facet of the group by the criterion of facet_on_surface.h, and grown over
// the facets around it that meet that criterion. Types are tried plane,
// cylinder, cone, sphere, torus, the first that fits being the group's (the
// proposals; which of them explain which facets, E decides: exact_facets.h).
// Of types that fit a grown support exactly alike, the one of least label
// cost (energy.h) is kept.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_HYPOTHESES_H_
#define MESHSEG_SRC_SEGMENT_EXACT_HYPOTHESES_H_

#include <optional>
#include <vector>

#include "meshseg/surface.h"
#include "segment/exact_fit.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// The order of simplicity of the types: plane 0, cylinder 1, cone 2,
// sphere 3, torus (and anything else) 4.
inline int Simplicity(SurfaceType type) {
  switch (type) {
    case SurfaceType::kPlane:
      return 0;
    case SurfaceType::kCylinder:
      return 1;
    case SurfaceType::kCone:
      return 2;
    case SurfaceType::kSphere:
      return 3;
    default:
      return 4;
  }
}

struct Hypothesis {
  SurfaceType type = SurfaceType::kPlane;
  Surface surface;           // in the FacetMesh's frame
  std::vector<int> support;  // facets on it, edge-connected to its seed, sorted
  // Seeded from disjoint pieces together (exact_joint_hypotheses.h): its
  // evidence is held by all its pieces, not by each.
  bool joint = false;
};

// The plane of facet f grown over the facets that lie in it (refitted as it
// grows); nullopt if f is degenerate or the plane holds no evidence.
std::optional<Hypothesis> PlaneAt(const FacetMesh& fm, int f, double tau);

// The first curved type that fits the facets around f exactly (f and the
// facets nearest it over edges at less than kSeedCreaseDeg, in rings or
// smoothest first, with kSeedCorners distinct corners, twice a torus's
// parameters; then fewer,
// down to a cylinder's least evidence, for a seed beside its face's border
// or on a small face), grown; nullopt if none holds evidence.
std::optional<Hypothesis> CurvedAt(const FacetMesh& fm, int f, double tau);
inline constexpr int kSeedCorners[] = {16, 12, 8};
inline constexpr double kSeedCreaseDeg = 60.0;

// Grows `h` over the facets edge-connected to its support that meet the
// criterion for its surface, refitting on what it holds (as every
// hypothesis above is grown).
void GrowHypothesis(const FacetMesh& fm, double tau, Hypothesis* h);

// True if facet f has a neighbour across an edge that lies in its plane
// (within tau), or the facets around it or around a neighbour fit a curved
// type exactly with f on it: the local test behind the share of exact
// facets (meshseg/segment.h: EstimateExactness). A sampled voxel surface
// (marching cubes) fails it at the facets that cut across the edges
// between its surfaces; a CAD tessellation has none. No growing.
bool ExplainedLocally(const FacetMesh& fm, int f, double tau);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_HYPOTHESES_H_
