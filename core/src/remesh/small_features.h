// Small curved features of a CAD tessellation: the input edges across which
// the surface bends with a radius too small for the remesh's edge length.
//
// A CAD export tessellates a cylinder or cone into facets: the angle θ
// between two neighbouring facets' normals and the facet's width w across
// their common edge give the radius, r ≈ w / θ (exact up to sin(θ/2)/(θ/2)).
// A uniform remesh at edge L resolves a hole of radius r with 2πr/L edges
// around; at r < 3 L (plate_holes.stl: r 3.38, L 1.66) the curvature fits of
// seeds 000/002 span the hole and its wall is lost. The remesh refines the
// surface around such edges (IsotropicRemesh, second pass).
#ifndef MESHSEG_REMESH_SMALL_FEATURES_H_
#define MESHSEG_REMESH_SMALL_FEATURES_H_

#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"

namespace meshseg::remesh_internal {

struct CurvedEdge {
  Eigen::Vector3d a, b;
  double radius = 0.0;  // radius of curvature across the edge, r ≈ w / θ
};

// Returns the edges of `tri` between two faces meeting at an angle under
// `feature_angle_deg` (a smooth edge of a faceted curved surface, not a
// crease) whose radius estimate is under `max_radius`. The width w is the
// larger of the two opposite corners' heights over the edge, so a sliver
// next to a wide face does not pass for a small radius.
std::vector<CurvedEdge> SmallRadiusEdges(const TriMesh& tri, double max_radius,
                                         double feature_angle_deg);

}  // namespace meshseg::remesh_internal

#endif  // MESHSEG_REMESH_SMALL_FEATURES_H_
