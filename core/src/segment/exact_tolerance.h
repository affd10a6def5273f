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

#include <vector>

#include <Eigen/Core>

namespace meshseg::segment_internal {

// The spacing of the representable values at the largest coordinate,
// for the finest representation that holds every coordinate exactly:
// float32, a decimal of k significant digits (k <= 15), else double.
double CoordinateResolution(const std::vector<Eigen::Vector3d>& positions);

// A vertex within kRoundingSpan resolutions of a surface lies on it: each
// of its three coordinates rounds by at most one resolution, and the
// surface, fitted to such vertices, is off by as much again.
inline constexpr double kRoundingSpan = 8.0;
// No tolerance below this fraction of the bounding-box diagonal: a
// modeller's own accuracy (OpenCASCADE's Precision::Confusion is 1e-7 mm on
// parts of 10-1000 mm; gmsh's tessellations of STEP files hold to 1e-9 of
// the diagonal, SOURCES.md) rather than the file's.
inline constexpr double kModellerAccuracy = 1e-8;

// Returns the tolerance tau, model units, for `positions` (absolute
// coordinates, as read) of a part with bounding-box `diagonal`.
double ExactTolerance(const std::vector<Eigen::Vector3d>& positions, double diagonal);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_TOLERANCE_H_
