// Which faces of the reconstructed surface the points support (issue 38:
// "no invented surface"). Where a scan has no points (occlusion gaps, the
// side a part stood on), the implicit f (ALGORITHMS.md S3) still has a zero set:
// linear fits extrapolated from the nearest supports, which the graph cut and
// marching tetrahedra turn into flaps and tubes hanging into empty space.
//
// The test is the sampling condition itself: on a surface sampled with local
// spacing s (the mean distance of a point to its 6 nearest), every point of
// the surface lies within about s of a sample, and noise moves a sample by
// at most the off-surface band of the outlier test (outliers.h). A face is
// supported when its centroid lies within `spacings` × s(p) + band of its
// nearest input point p, s measured at p: the cloud's own density where the
// face is, not a global constant, so sparse but genuine regions (grazing
// views, far from the scanner) keep their surface.
//
// The mesh itself is piecewise linear: where its faces are coarser than the
// points (a refine edge capped by the face budget on a dense cloud), a face
// whose corners lie on the points chords the surface between them, by its
// sagitta ≈ e² / (8 R) for edge e on a surface of curvature radius R, or by
// more where a crease runs through the face. Its centroid then lies that far
// off the points although the face is on the surface. So the reach grows by
// the face's own chord error, the largest distance of its centroid from the
// tangent planes at its corners (normal to the area-weighted vertex normals).
// That bounds how far the surface can lie off the face: along an edge whose
// normals turn by θ, a smooth surface lies e θ / 8 off its midpoint (the
// sagitta) and either end's tangent plane e θ / 4; a crease midway between
// the ends lies e tan(θ/2) / 2 ≈ e θ / 4 off it. Only a face that can be such
// a chord gains:
// - its three corners are supported (a flap into empty space has corners
//   off the points);
// - its edges are no longer than the mesh's resolution (`max_chord_edge`):
//   a longer face is a marching-tetrahedra tent spanning between two faces
//   through the solid (refine.h), whose hole the patch closes onto the seen
//   planes (seen_planes.h).
// A face in the tangent planes of its corners (a flap or membrane continuing
// the seen surface) gains nothing.
//
// The factor `spacings` and the band are room for gaps between samples and
// for noise along the normal; past the border of the sampled area (an
// occlusion edge, the side a part stood on) they would let the surface run on
// by 2 s + band beyond the last samples, and the patch closing the unseen side
// then spans a loop that far out (below a flat bottom, say). The true border
// lies between the last row of samples and the next, missing one. So a face
// whose centroid is more than kBorderSpacings × s from its nearest point
// along the surface (in the face's plane) is supported only if the points
// around it surround it: their directions, projected into the points'
// least-squares plane (the face's plane when they lie along one line), leave
// no angular gap over π (the angle criterion for boundaries of point
// sets, Bendels, Schnabel & Klein 2006, "Detecting holes in point set
// surfaces"). Inside the sampled area a centroid between samples is
// surrounded; beyond its border every nearby point lies on one side. The
// points looked at are those within twice the reach: a gap between samples
// that the reach bridges from both sides (random sampling leaves voids of
// several local spacings) has points across it and stays supported.
#ifndef MESHSEG_RECONSTRUCT_SUPPORT_H_
#define MESHSEG_RECONSTRUCT_SUPPORT_H_

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"
#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// Neighbours whose mean distance is the local spacing s (as MeanNeighborDistances).
inline constexpr int kSpacingNeighbors = 6;
// Tangential reach of the support beyond the border of the sampled area, in
// local spacings: half the gap to the next, missing, row of samples.
inline constexpr double kBorderSpacings = 0.5;

// The local spacing s at input point `p` (one of `points`): the mean distance
// to its kSpacingNeighbors nearest others. `near` and `dist2` are scratch.
double SpacingAtPoint(const Eigen::Vector3d& p, const mesh_internal::PointIndex& index,
                      std::vector<uint32_t>* near, std::vector<double>* dist2);

// The chord error of a face with corners `corner` whose surface has unit
// normals `normal` there: the largest distance of the centroid from the
// tangent plane at a corner. On a sphere of radius R it is r² / R for
// circumradius r, twice the centroid's depth below the sphere (see above).
double ChordError(const std::array<Eigen::Vector3d, 3>& corner,
                  const std::array<Eigen::Vector3d, 3>& normal);

// Returns one flag per face of `tri`: 1 when the face is supported by
// `points` (indexed by `index`, at least kSpacingNeighbors + 1 of them):
// within `spacings` × s + `band` of its nearest point, and, if more than
// kBorderSpacings × s from it along the face, surrounded by the points within
// twice that reach (see above); the reach grows by the face's chord error when
// its corners are within reach of the points and its edges within
// `max_chord_edge` (0: never); `band` and `max_chord_edge` in model units.
std::vector<uint8_t> SupportedFaces(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                    const mesh_internal::PointIndex& index, double spacings,
                                    double band, double max_chord_edge);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SUPPORT_H_
