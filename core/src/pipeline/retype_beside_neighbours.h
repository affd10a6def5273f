// Point clouds: a curved region's type decided again on the points its own
// surface explains better than its neighbours' surfaces do.
#ifndef MESHSEG_PIPELINE_RETYPE_BESIDE_NEIGHBOURS_H_
#define MESHSEG_PIPELINE_RETYPE_BESIDE_NEIGHBOURS_H_

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// The regions sharing a mesh edge with each region: one sorted list per
// region id (0 .. region_count - 1); faces labelled < 0 have no region.
std::vector<std::vector<int>> RegionNeighbours(const TriMesh& mesh,
                                               std::span<const int> face_labels,
                                               std::size_t region_count);

// The type decision (ALGORITHMS.md S1, with RetypeToPoints' criterion) made
// again for each torus, cone or sphere region on its points
// (points_of_region, its band), against the hypothesis that some of them
// are its neighbours' (`neighbours`, RegionNeighbours; analytic regions
// with points of their own): each point on the nearest of an axial type's
// surface and the neighbours' surfaces.
//
// The reconstruction rounds a crease over about a spacing, and the region of
// a narrow band between two creases (a chamfer) can reach a few spacings
// over both edges into its neighbours: its band then holds their points,
// which lie on their own surfaces at an angle to the band's, and a fit to
// all of them bends into a more general type (a torus for a cone, both ends
// turning into the neighbours). Where two surfaces cross at an angle each
// point near the edge lies on one of them, so the band's true type, fitted
// beside its neighbours, explains all the points at the noise. Where a
// region meets its neighbours tangentially (a round) its points leave each
// neighbour gradually, and a limit type beside them leaves the region's
// curvature between the tangent edges unexplained: the region's own type
// fits better. The limit is fitted alternately to the points it explains
// better than every neighbour (k-surfaces: assign, refit, until the
// assignment stays) and scored on all the band's points, each at its
// distance to the nearest of the fit and the neighbours' surfaces; the
// region's type is scored on all of them at its own surface. A limit of the
// region's type in its axial family (a cylinder or cone of a torus, a
// cylinder of a cone), or a cylinder or cone in place of a sphere, takes
// over when it is near the cloud's noise `sigma` (not the region's own
// scatter, which the neighbours' points it holds
// inflate: a torus fitted badly to a fillet's band and its neighbours'
// points is no measure of what a cone beside them must meet) and scores
// less than kScoreMargin above the region's type (its extra parameters
// must buy that much), or, in place of a sphere (no limit of it, nor it of
// them), kScoreMargin below it. Over a band a few spacings wide a sphere
// meets a cone's straight profile within its sagitta, and on a chamfer
// whose band holds the rounded creases beyond both edges it fits about as
// well with 2 parameters fewer; beside the neighbours the cone explains
// the band at the noise and the sagitta is the sphere's alone. A region
// whose points its neighbours' surfaces explain near the noise without it
// is a fragment of theirs and is left alone. No plane: a plane fits any
// narrow enough strip of a curved surface within the noise, and
// RetypeToPoints has tried it on all the band.
// A retyped region takes the fit on the points it explains, and a surface of
// its own (TakeOwnSurface). Returns how many regions changed type.
int RetypeBesideNeighbours(std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                           std::span<const std::vector<int>> neighbours, double sigma,
                           std::vector<Region>* regions, std::vector<SharedSurface>* surfaces);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_RETYPE_BESIDE_NEIGHBOURS_H_
