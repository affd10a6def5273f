// Sharp or smooth, convex or concave: the angle between the two regions'
// surface normals along a curve (each oriented outward by the faces next to
// the edge) and the sign of the turn from the left to the right surface.
#ifndef MESHSEG_SRC_TOPOLOGY_CURVE_CHARACTER_H_
#define MESHSEG_SRC_TOPOLOGY_CURVE_CHARACTER_H_

#include <span>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "meshseg/topology.h"

namespace meshseg::topology_internal {

struct CurveCharacter {
  double normal_angle_deg = 0.0;
  bool sharp = false;
  CurveConvexity convexity = CurveConvexity::kBorder;
};

// Returns the character of `curve` (vertices, left/right regions set) on
// `mesh`. Convexity compares the surfaces' normals one edge length away from
// the curve on either side, so tangent (smooth) curves get the sign of the
// fitted curvature rather than of the mesh noise.
CurveCharacter CurveCharacterOf(const TriMesh& mesh, std::span<const int> face_labels,
                                std::span<const Region> regions, const BoundaryCurve& curve,
                                double sharp_angle_deg);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_CURVE_CHARACTER_H_
