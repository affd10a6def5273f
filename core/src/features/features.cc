// RecognizeFeatures: check the input, then fillets, corner blends,
// extrusions and revolutions in that order.
#include "meshseg/features.h"

#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "features/extrusions.h"
#include "features/feature_geometry.h"
#include "features/fillets.h"
#include "features/revolutions.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

absl::Status ValidateParams(const FeatureParams& p) {
  if (!(p.angle_tolerance_deg > 0.0 && p.angle_tolerance_deg < 45.0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "features: angle_tolerance_deg = ", p.angle_tolerance_deg, " must be in (0, 45)"));
  }
  if (!(p.distance_tolerance >= 0.0) || !std::isfinite(p.distance_tolerance)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "features: distance_tolerance = ", p.distance_tolerance, " must be >= 0"));
  }
  return absl::OkStatus();
}

absl::Status ValidateInput(const Topology& topology, std::span<const Region> regions) {
  if (topology.regions.size() != regions.size()) {
    return absl::InvalidArgumentError(absl::StrCat("features: topology has ",
                                                   topology.regions.size(), " regions, expected ",
                                                   regions.size()));
  }
  const int n = static_cast<int>(regions.size());
  for (const Adjacency& arc : topology.adjacency) {
    if (arc.region_a < 0 || arc.region_b >= n || arc.region_a >= arc.region_b) {
      return absl::InvalidArgumentError(absl::StrCat("features: adjacency (", arc.region_a, ", ",
                                                     arc.region_b, ") outside [0, ", n, ")"));
    }
    for (const int c : arc.curves) {
      if (c < 0 || c >= static_cast<int>(topology.curves.size())) {
        return absl::InvalidArgumentError(absl::StrCat("features: adjacency names curve ", c,
                                                       " of ", topology.curves.size()));
      }
    }
  }
  return absl::OkStatus();
}

}  // namespace

const char* FeatureTypeName(FeatureType type) {
  switch (type) {
    case FeatureType::kFilletTorusSpherePlane: return "fillet_torus_sphere_plane";
    case FeatureType::kFilletTorusCylinderPlane: return "fillet_torus_cylinder_plane";
    case FeatureType::kFilletCylinderPlanes: return "fillet_cylinder_planes";
    case FeatureType::kCornerBlendSphere: return "corner_blend_sphere";
    case FeatureType::kCornerBlendTorus: return "corner_blend_torus";
    case FeatureType::kLinearExtrusion: return "linear_extrusion";
    case FeatureType::kRevolution: return "revolution";
  }
  return "linear_extrusion";
}

absl::StatusOr<std::vector<Feature>> RecognizeFeatures(const Topology& topology,
                                                       std::span<const Region> regions,
                                                       const FeatureParams& params) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(ValidateInput(topology, regions));
  const features_internal::Tolerances tol{
      params.angle_tolerance_deg * std::numbers::pi / 180.0,
      params.distance_tolerance * topology.mean_edge_length};
  const features_internal::RegionGraph graph(topology);
  std::vector<Feature> out = features_internal::FindEdgeFillets(topology, regions, graph, tol);
  const std::vector<Feature> blends =
      features_internal::FindCornerBlends(topology, regions, graph, out);
  out.insert(out.end(), blends.begin(), blends.end());
  const std::vector<Feature> extrusions =
      features_internal::FindExtrusions(topology, regions, graph, tol);
  out.insert(out.end(), extrusions.begin(), extrusions.end());
  const std::vector<Feature> revolutions =
      features_internal::FindRevolutions(topology, regions, graph, tol);
  out.insert(out.end(), revolutions.begin(), revolutions.end());
  for (size_t k = 0; k < out.size(); ++k) out[k].id = static_cast<int>(k);
  return out;
}

}  // namespace meshseg
