// The distance within which the vertices of an exact tessellation lie on
// their surfaces: the rounding of the numbers the file carries, not a
// fraction of an edge. A CAD exporter computes each vertex on its surface
// in double precision and writes it with the digits of its format: binary
// STL holds float32 (half a unit in the last place: 6e-8 of the coordinate),
// ASCII STL and OBJ writers print 6 to 17 significant digits. The rounding
// is relative to the coordinates themselves, so a part far from the origin
// rounds coarser than its size suggests; the tolerance follows the largest
// coordinate, never the part's size alone.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_TOLERANCE_H_
#define MESHSEG_SRC_SEGMENT_EXACT_TOLERANCE_H_

#include <Eigen/Core>
#include <vector>

#include "segment/facet_mesh.h"

namespace meshseg::segment_internal {

// The spacing of the representable values at the largest coordinate,
// for the finest representation that holds every coordinate exactly:
// float32, a decimal of k significant digits (k <= 15), else double. A
// unit conversion after the rounding (x 1000, x 25.4) is no exact operation
// in binary: a coordinate within a few units in its last place of a float32
// times a unit factor (a power of ten, or 25.4 times one) counts as that,
// and the spacing is float32's in the file's own unit, times the factor.
double CoordinateResolution(const std::vector<Eigen::Vector3d>& positions);

// A vertex within kRoundingSpan resolutions of a surface lies on it: each
// of its three coordinates rounds by at most one resolution, and the
// surface, fitted to such vertices, is off by as much again.
inline constexpr double kRoundingSpan = 8.0;
// No tolerance below this fraction of the bounding-box diagonal: float32,
// the STL format's own numbers, rounds at 6e-8 of a coordinate, and a file
// may carry that rounding under more digits (an STL exported in metres,
// scaled to millimetres and printed with 9 digits); a modeller's own accuracy
// (OpenCASCADE's Precision::Confusion, 1e-7 mm) is finer still on parts of
// 1 mm and more. The surfaces of a part are never this close without being
// one.
inline constexpr double kModellerAccuracy = 1e-7;

// A file can be rounder than its numbers say: a float32 STL in metres
// scaled to millimetres and printed with 9 digits carries float32's
// rounding, not the 9 digits'. The rounding the corners do carry shows where
// facets meet in a plane: the distance of a neighbour's far corner from a
// facet's plane is the rounding there (and a sag or a crease elsewhere, far
// larger). The floor is the kFloorQuantile of those distances under
// kLoosestExact of the diagonal (the loosest rounding a file of exact
// vertices can have), taken once kMinFloorSamples of them are found.
inline constexpr double kLoosestExact = 1e-5;
inline constexpr double kFloorQuantile = 0.9;
inline constexpr int kMinFloorSamples = 20;
// The floor is a corner's rounding; a fit through such corners is off by as
// much again, and a corner from the fit by twice that.
inline constexpr double kFloorSpan = 4.0;

// Returns the rounding floor of `fm` (model units; 0 when too few facets
// meet in a plane).
double PlanarityFloor(const FacetMesh& fm);

// Returns the tolerance tau, model units, for `positions` (absolute
// coordinates, as read) of a part with bounding-box `diagonal` and rounding
// floor `floor`: the largest of the three bounds above.
double ExactTolerance(const std::vector<Eigen::Vector3d>& positions, double diagonal, double floor);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_TOLERANCE_H_
