#include <type_traits>
#include <variant>

#include "meshseg/proto/convert.h"
#include "proto/src/brep_to_proto.h"
#include "proto/src/mesh_geometry_proto.h"
#include "proto/src/subdivision_proto.h"
#include "proto/src/topology_to_proto.h"

namespace meshseg {
namespace {

v1::SurfaceType ToProto(SurfaceType type) {
  switch (type) {
    case SurfaceType::kPlane: return v1::SURFACE_TYPE_PLANE;
    case SurfaceType::kCylinder: return v1::SURFACE_TYPE_CYLINDER;
    case SurfaceType::kCone: return v1::SURFACE_TYPE_CONE;
    case SurfaceType::kSphere: return v1::SURFACE_TYPE_SPHERE;
    case SurfaceType::kTorus: return v1::SURFACE_TYPE_TORUS;
    case SurfaceType::kQuadric: return v1::SURFACE_TYPE_QUADRIC;
    case SurfaceType::kFreeform: return v1::SURFACE_TYPE_FREEFORM;
  }
  return v1::SURFACE_TYPE_UNSPECIFIED;
}

v1::SegmentationPath ToProto(SegmentationPath path) {
  switch (path) {
    case SegmentationPath::kScan: return v1::SEGMENTATION_PATH_SCAN;
    case SegmentationPath::kExactFacets: return v1::SEGMENTATION_PATH_EXACT_FACETS;
    case SegmentationPath::kRemeshed: return v1::SEGMENTATION_PATH_REMESHED;
  }
  return v1::SEGMENTATION_PATH_UNSPECIFIED;
}

// Fills the surface oneof of `out` (a v1::Region or v1::SharedSurface) from
// the alternative `surface` holds.
template <typename Message>
void SetSurface(const Surface& surface, Message* out) {
  std::visit(
      [out](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          SetVec3(s.point, out->mutable_plane()->mutable_point());
          SetVec3(s.normal, out->mutable_plane()->mutable_normal());
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          auto* c = out->mutable_cylinder();
          SetVec3(s.axis_origin, c->mutable_axis_origin());
          SetVec3(s.axis_direction, c->mutable_axis_direction());
          c->set_radius(s.radius);
        } else if constexpr (std::is_same_v<T, Cone>) {
          auto* c = out->mutable_cone();
          SetVec3(s.apex, c->mutable_apex());
          SetVec3(s.axis_direction, c->mutable_axis_direction());
          c->set_half_angle(s.half_angle);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          SetVec3(s.center, out->mutable_sphere()->mutable_center());
          out->mutable_sphere()->set_radius(s.radius);
        } else if constexpr (std::is_same_v<T, Torus>) {
          auto* t = out->mutable_torus();
          SetVec3(s.center, t->mutable_center());
          SetVec3(s.axis_direction, t->mutable_axis_direction());
          t->set_major_radius(s.major_radius);
          t->set_minor_radius(s.minor_radius);
        } else {
          static_assert(std::is_same_v<T, Quadric>);
          for (double c : s.c) out->mutable_quadric()->add_coefficients(c);
        }
      },
      surface);
}

void SetMeshInfo(const MeshStats& stats, v1::MeshInfo* out) {
  out->set_vertex_count(stats.vertex_count);
  out->set_face_count(stats.input_face_count);
  out->set_mean_edge_length(stats.mean_edge_length);
  out->set_dropped_face_count(stats.dropped_face_count);
  out->set_input_vertex_count(stats.input_vertex_count);
  out->set_mesh_face_count(stats.face_count);
  out->set_boundary_edge_count(stats.boundary_edge_count);
  out->set_component_count(stats.component_count);
  SetVec3(stats.bbox_min, out->mutable_bbox_min());
  SetVec3(stats.bbox_max, out->mutable_bbox_max());
}

}  // namespace

v1::SegmentationResult ToProto(const PipelineResult& result) {
  v1::SegmentationResult out;
  SetMeshInfo(result.mesh, out.mutable_mesh());
  out.mutable_face_labels()->Add(result.face_labels.begin(), result.face_labels.end());
  out.mutable_vertex_labels()->Add(result.vertex_labels.begin(), result.vertex_labels.end());
  for (const Region& region : result.regions) {
    v1::Region* r = out.add_regions();
    r->set_id(region.id);
    r->set_type(ToProto(region.type));
    r->set_face_count(region.face_count);
    r->set_vertex_count(region.vertex_count);
    r->set_area(region.area);
    r->set_rms_distance(region.rms_distance);
    r->set_max_distance(region.max_distance);
    // A freeform region keeps the quadric it was grown with as its surface.
    SetSurface(region.surface, r);
    r->set_surface_id(region.surface_id);
  }
  SetSubdivisions(result.subdivisions, &out);
  for (const SharedSurface& surface : result.surfaces) {
    v1::SharedSurface* s = out.add_surfaces();
    s->set_id(surface.id);
    s->set_type(ToProto(surface.type));
    SetSurface(surface.surface, s);
    s->mutable_regions()->Add(surface.regions.begin(), surface.regions.end());
    s->set_rms_distance(surface.rms_distance);
    s->set_max_distance(surface.max_distance);
  }
  v1::Estimates* e = out.mutable_estimates();
  e->set_noise_sigma(result.estimates.noise_sigma);
  e->set_distance_tolerance(result.estimates.distance_tolerance);
  e->set_angle_tolerance_deg(result.estimates.angle_tolerance_deg);
  e->set_sharp_threshold(result.estimates.sharp_threshold);
  e->set_remesh_edge_length(result.remesh_edge_length);
  e->set_remesh_face_count(result.remesh_face_count);
  e->set_remesh_fine_edge_length(result.remesh_fine_edge_length);
  e->set_simplified_face_count(result.simplified_face_count);
  e->set_simplified_hausdorff(result.simplified_hausdorff);
  out.set_binary_occupancy(result.binary_occupancy);
  if (result.from_volume) {
    v1::VolumeSource* v = out.mutable_volume();
    const VolumeGeometry& g = result.volume.geometry;
    v->mutable_dims()->Add(g.dims.begin(), g.dims.end());
    const Eigen::Vector3d spacing = g.Spacing();
    v->mutable_spacing()->set_x(spacing.x());
    v->mutable_spacing()->set_y(spacing.y());
    v->mutable_spacing()->set_z(spacing.z());
    v->mutable_origin()->set_x(g.origin.x());
    v->mutable_origin()->set_y(g.origin.y());
    v->mutable_origin()->set_z(g.origin.z());
    v->set_voxel_type(VoxelTypeName(result.volume.type));
    v->set_format(FileFormatName(result.volume.format));
    v->set_iso_value(result.iso_value);
  }
  e->set_segmentation_path(ToProto(result.estimates.path));
  e->set_exact_tolerance(result.estimates.exact_tolerance);
  e->set_exact_share(result.estimates.exact_share);
  SetTopology(result.topology, result.features, &out);
  out.mutable_point_labels()->Add(result.point_labels.begin(), result.point_labels.end());
  for (const uint8_t filled : result.face_filled) out.add_face_filled(filled != 0);
  out.set_point_outlier_count(result.point_outlier_count);
  out.mutable_mesh()->set_filled_face_count(result.filled_face_count);
  out.mutable_mesh()->set_filled_area(result.filled_area);
  SetBrep(result, &out);
  if (result.mesh_geometry) SetMeshGeometry(*result.mesh_geometry, out.mutable_mesh_geometry());
  out.set_length_unit(result.length_unit);
  return out;
}

}  // namespace meshseg
