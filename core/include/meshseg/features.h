// File: features.h
// -----------------------------------------------------------------------------
// The `features` stage: higher-level surfaces recognised from the regions'
// fitted surfaces and their adjacency. Seed 002 D1–D3:
//   fillets   FLT1 torus between a sphere and a plane, FLT2 torus between a
//             cylinder and a plane, FLT3 cylinder between two planes, FLT4
//             corner blend (sphere or torus) among three FLT3 fillets;
//   linear extrusions (planes and cylinders sharing one direction);
//   surfaces of revolution (planes, cylinders, cones, spheres, tori sharing
//             one axis).
//
// In: the Topology of a segmentation and its Regions. Out: a list of Feature.
#ifndef MESHSEG_FEATURES_H_
#define MESHSEG_FEATURES_H_

#include <span>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/segment.h"
#include "meshseg/topology.h"

namespace meshseg {

struct FeatureParams {
  // Axes and normals count as parallel / perpendicular within this, degrees.
  // Seed 002 th_norm (8).
  double angle_tolerance_deg = 8.0;
  // Axes coincide, and centres and apexes lie on an axis, within this, in
  // l_avg (Topology::mean_edge_length).
  double distance_tolerance = 2.0;
};

enum class FeatureType {
  kFilletTorusSpherePlane,    // FLT1
  kFilletTorusCylinderPlane,  // FLT2
  kFilletCylinderPlanes,      // FLT3
  kCornerBlendSphere,         // FLT4: three FLT3 fillets all convex or all concave
  kCornerBlendTorus,          // FLT4': three FLT3 fillets of mixed convexity
  kLinearExtrusion,
  kRevolution,
};

// "fillet_torus_sphere_plane", "fillet_torus_cylinder_plane",
// "fillet_cylinder_planes", "corner_blend_sphere", "corner_blend_torus",
// "linear_extrusion", "revolution".
const char* FeatureTypeName(FeatureType type);

struct Feature {
  int id = 0;
  FeatureType type = FeatureType::kLinearExtrusion;
  // Fillets: the blend region first, then the regions it joins (FLT1: sphere,
  // plane; FLT2: cylinder, plane; FLT3: the two planes; FLT4: the three FLT3
  // fillets). Extrusions and revolutions: the member regions, ascending.
  std::vector<int> regions;
  // Fillets: the blend radius (torus minor radius, cylinder or sphere
  // radius), model units; 0 otherwise.
  double radius = 0.0;
  // Fillets: true if the material lies inside the blend's curvature (a
  // rounded edge), false for a concave blend (a rounded groove or root).
  bool convex = false;
  // Fillets FLT3: angle between the two planes' outward normals (the arc the
  // fillet turns through), degrees, in (0, 180); 0 otherwise.
  double opening_angle_deg = 0.0;
  // Extrusions: the unit extrusion direction. Revolutions and FLT1/2/3: the
  // unit axis direction (FLT4: zero).
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  // Revolutions and FLT1/2/3: a point on the axis; extrusions: zero.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

// Returns the features of a segmentation, fillets first (by blend region),
// then corner blends, extrusions and revolutions.
// Inputs: `topology` from ExtractTopology on the same `regions`.
// Outputs: features[k].id == k. A region may belong to several features
// (e.g. an FLT3 fillet that is also part of an extrusion).
// Errors: INVALID_ARGUMENT for bad params or a topology whose region count
// differs from regions.size() or whose adjacency names unknown regions.
absl::StatusOr<std::vector<Feature>> RecognizeFeatures(const Topology& topology,
                                                       std::span<const Region> regions,
                                                       const FeatureParams& params = {});

}  // namespace meshseg

#endif  // MESHSEG_FEATURES_H_
