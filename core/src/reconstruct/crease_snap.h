// Puts the creases found by the projection (crease.h) into the mesh's
// edges (issue 38 item 3). A vertex projected onto the nearest point of two
// planes lies on one plane's part of the surface or on their line, but a
// triangle with corners on both parts is a chord that cuts the edge off, by
// up to about half its edge length at a right angle. As in the Edge
// Sharpener (Attene, Falcidieno, Rossignac, Spagnuolo 2003), which restores
// the sharp edges of remeshed CAD surfaces by putting vertices on the
// planes' intersection: every mesh edge whose ends lie on different parts
// of a crease gets a vertex on the crease line, where it crosses the
// bisecting plane (the edge is split there and the new vertex put on the
// line), or, when that point is near one end, that end is moved onto the
// line (no sliver). A triangle with corners on both parts then has a vertex
// on the line in each of its crossing edges, so its pieces lie in one plane
// each. A move that would fold or collapse a triangle is not made.
#ifndef MESHSEG_RECONSTRUCT_CREASE_SNAP_H_
#define MESHSEG_RECONSTRUCT_CREASE_SNAP_H_

#include <utility>
#include <vector>

#include "meshseg/mesh.h"
#include "reconstruct/crease.h"

namespace meshseg::reconstruct_internal {

// What SnapToCreases did.
struct CreaseSnap {
  int moved = 0;     // vertices moved onto a crease line
  int inserted = 0;  // vertices added on a crease line (edge splits)
};

// A crossing point nearer to an end than this fraction of the edge moves
// that end instead of splitting the edge.
inline constexpr double kCreaseSnapFraction = 0.25;

// Puts vertices of `mesh` on crease lines as above; `creases` gives the
// crease found at each vertex that has one (ProjectToPoints). An edge counts
// as crossing when the crease of either end, or else of a neighbour of an
// end, puts its ends on different parts (a vertex a few spacings from the
// edge may see too few points of the other face to fit its plane). The caller
// updates normals and face maps.
CreaseSnap SnapToCreases(const std::vector<std::pair<int, Crease>>& creases, TriMesh* mesh);

// Points of the region outside a convex crease (beyond both faces) all have
// the same nearest point on the line at each position along it, so
// vertices there can land on one point, or three on the line. Removes the
// triangles that leaves flat (area under kFlatTriangle × longest edge²): a
// cap by flipping its longest edge, a needle (shortest edge under
// kNeedleEdge × longest) or a cap that cannot flip by collapsing its
// shortest edge, each only where the
// mesh stays a manifold (OpenMesh's link condition, is_flip_ok); then
// removes the deleted elements (vertex and face handles change). Returns
// the number of collapses and flips.
inline constexpr double kFlatTriangle = 1e-8;
inline constexpr double kNeedleEdge = 0.05;
int RemoveFlatTriangles(TriMesh* mesh);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_CREASE_SNAP_H_
