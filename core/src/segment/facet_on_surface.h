// The exact-facet criterion: when a facet of an exact tessellation belongs
// to a surface.
//
// A CAD exporter tessellates each face of a B-rep with facets whose corners
// it computes on the face's surface; the facets are chords of the surface,
// under it by their sag. So a facet f is consistent with a surface S iff
//  (1) its three corners lie on S within the tolerance tau (the rounding of
//      the file's numbers, exact_tolerance.h), or on a chord of S: a corner
//      a tessellator put on an edge of a flat facet to meet the next face
//      lies on the segment between two of its neighbours (within tau), and
//      counts as on S when both ends of it are;
//  (2) its plane is a chord plane of S over it: the angle between f's normal
//      and S's normal at the foot of f's centroid is at most the angle by
//      which S's normal turns from there to f's corners (the spread), plus
//      the tilt that corners at depths differing by up to the facet's sag
//      (the centroid's distance to S) and tau give its plane over its least
//      height h: atan(2 (tau + sag) / h);
//  (3) its centroid lies under S by no more than a point within r of
//      corners on S can: tau + the sag of a sphere of S's largest curvature
//      over r (r the farthest corner from the centroid);
//  (4) the spread is under kMaxSpreadDeg: a facet over which the surface
//      turns by a half turn or more approximates nothing of it. (CAD fans on
//      small holes do span 100-180 degrees: a coarse export may put only a
//      few facets around a hole.)
//  (5) S's normal at every corner is on the same side of f's plane as at
//      the others, at less than a right angle to f's normal by more than the
//      tilt tau gives f's plane over its least height: the surface over a
//      chord facet is a graph over the facet's plane. (A sliver of a disc
//      fanned from a rim vertex has all its corners on the rim's cylinder
//      and, spanning a quarter turn or more, passes (2)-(4); its normal,
//      along the axis, is at a right angle to the cylinder's.)
// On a plane the spread is 0, and (2)-(3) say that f lies in it. A facet of
// an annular end face whose corners all lie on the rim circle has them on
// the cylinder too, but its normal is along the axis, at 90 degrees to
// every normal of the cylinder: (2) keeps it off, and (3) where a sliver of
// a fan tilts its allowance in (2) up, its centroid lying deep inside the
// rim, far under the cylinder's sag over the facet. A flat face cutting a
// cylinder along two rulings is a chord plane of it; it passes (1)-(3) and
// is kept off by (4) when it spans a half turn, else only by the
// competition of explanations in exact_facets.h.
#ifndef MESHSEG_SRC_SEGMENT_FACET_ON_SURFACE_H_
#define MESHSEG_SRC_SEGMENT_FACET_ON_SURFACE_H_

#include "meshseg/surface.h"
#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

inline constexpr double kMaxSpreadDeg = 90.0;

// True if facet f of `fm` is consistent with `surface` (in fm's frame)
// within `tau`, as above.
bool FacetOnSurface(const FacetMesh& fm, int f, const Surface& surface, double tau);

// True if vertex v lies on a chord of `surface` (test (1) above): within
// `tau` of the segment between its chord_ends, both within `tau` of it.
bool ChordOnSurface(const FacetMesh& fm, int v, const Surface& surface, double tau);

// True if every corner of facet f lies within `tau` of `surface`: test (1)
// alone (without chords), for a quick rejection.
bool CornersOnSurface(const FacetMesh& fm, int f, const Surface& surface, double tau);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FACET_ON_SURFACE_H_
