// A SegmentationResult message back into core types (the inverse of
// ToProto), for tools that start from a saved result (`meshseg brep`).
#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"
#include "proto/src/mesh_geometry_proto.h"
#include "proto/src/subdivision_proto.h"
#include "proto/src/topology_from_proto.h"

namespace meshseg {
namespace {

absl::Status Bad(const std::string& what) {
  return absl::InvalidArgumentError(absl::StrCat("result: ", what));
}

absl::StatusOr<SurfaceType> TypeFromProto(v1::SurfaceType type, int region) {
  switch (type) {
    case v1::SURFACE_TYPE_PLANE: return SurfaceType::kPlane;
    case v1::SURFACE_TYPE_CYLINDER: return SurfaceType::kCylinder;
    case v1::SURFACE_TYPE_CONE: return SurfaceType::kCone;
    case v1::SURFACE_TYPE_SPHERE: return SurfaceType::kSphere;
    case v1::SURFACE_TYPE_TORUS: return SurfaceType::kTorus;
    case v1::SURFACE_TYPE_QUADRIC: return SurfaceType::kQuadric;
    case v1::SURFACE_TYPE_FREEFORM: return SurfaceType::kFreeform;
    default: return Bad(absl::StrCat("region ", region, " has no surface type"));
  }
}

absl::StatusOr<Surface> SurfaceFromProto(const v1::Region& r) {
  switch (r.surface_case()) {
    case v1::Region::kPlane:
      return Surface(Plane{FromProto(r.plane().point()), FromProto(r.plane().normal())});
    case v1::Region::kCylinder:
      return Surface(Cylinder{FromProto(r.cylinder().axis_origin()),
                              FromProto(r.cylinder().axis_direction()), r.cylinder().radius()});
    case v1::Region::kCone:
      return Surface(Cone{FromProto(r.cone().apex()), FromProto(r.cone().axis_direction()),
                          r.cone().half_angle()});
    case v1::Region::kSphere:
      return Surface(Sphere{FromProto(r.sphere().center()), r.sphere().radius()});
    case v1::Region::kTorus:
      return Surface(Torus{FromProto(r.torus().center()), FromProto(r.torus().axis_direction()),
                           r.torus().major_radius(), r.torus().minor_radius()});
    case v1::Region::kQuadric: {
      if (r.quadric().coefficients_size() != 10) {
        return Bad(absl::StrCat("region ", r.id(), " quadric has ",
                                r.quadric().coefficients_size(), " coefficients, not 10"));
      }
      Quadric q;
      for (int i = 0; i < 10; ++i) q.c[i] = r.quadric().coefficients(i);
      return Surface(q);
    }
    default: return Bad(absl::StrCat("region ", r.id(), " has no surface parameters"));
  }
}

}  // namespace

absl::StatusOr<PipelineResult> FromProto(const v1::SegmentationResult& result) {
  PipelineResult out;
  out.mesh.vertex_count = result.mesh().vertex_count();
  out.mesh.input_face_count = result.mesh().face_count();
  out.mesh.face_count = result.mesh().mesh_face_count();
  out.mesh.mean_edge_length = result.mesh().mean_edge_length();
  out.face_labels.assign(result.face_labels().begin(), result.face_labels().end());
  out.vertex_labels.assign(result.vertex_labels().begin(), result.vertex_labels().end());
  for (int k = 0; k < result.regions_size(); ++k) {
    const v1::Region& r = result.regions(k);
    if (r.id() != k) return Bad(absl::StrCat("region ", k, " has id ", r.id()));
    Region region;
    region.id = k;
    MESHSEG_ASSIGN_OR_RETURN(region.type, TypeFromProto(r.type(), k));
    MESHSEG_ASSIGN_OR_RETURN(region.surface, SurfaceFromProto(r));
    region.face_count = r.face_count();
    region.vertex_count = r.vertex_count();
    region.area = r.area();
    region.rms_distance = r.rms_distance();
    region.max_distance = r.max_distance();
    out.regions.push_back(region);
  }
  MESHSEG_ASSIGN_OR_RETURN(out.subdivisions, SubdivisionsFromProto(result));
  out.estimates.mean_edge_length = result.mesh().mean_edge_length();
  out.estimates.noise_sigma = result.estimates().noise_sigma();
  out.estimates.distance_tolerance = result.estimates().distance_tolerance();
  out.estimates.angle_tolerance_deg = result.estimates().angle_tolerance_deg();
  out.estimates.sharp_threshold = result.estimates().sharp_threshold();
  out.remesh_edge_length = result.estimates().remesh_edge_length();
  out.remesh_face_count = result.estimates().remesh_face_count();
  out.remesh_fine_edge_length = result.estimates().remesh_fine_edge_length();
  MESHSEG_ASSIGN_OR_RETURN(out.topology, TopologyFromProto(result));
  out.topology.mean_edge_length = result.mesh().mean_edge_length();
  out.point_labels.assign(result.point_labels().begin(), result.point_labels().end());
  out.from_point_cloud = result.point_labels_size() > 0;
  out.point_count = result.point_labels_size();
  if (result.point_outlier_count() < 0 || result.point_outlier_count() > out.point_count) {
    return Bad(absl::StrCat("point_outlier_count ", result.point_outlier_count(), " outside [0, ",
                            out.point_count, "] (the point labels)"));
  }
  out.point_outlier_count = result.point_outlier_count();
  if (result.face_filled_size() != 0 && result.face_filled_size() != result.face_labels_size()) {
    return Bad(absl::StrCat("face_filled has ", result.face_filled_size(), " entries for ",
                            result.face_labels_size(), " faces"));
  }
  out.face_filled.assign(result.face_filled().begin(), result.face_filled().end());
  out.filled_face_count = result.mesh().filled_face_count();
  out.filled_area = result.mesh().filled_area();
  if (result.has_mesh_geometry()) {
    MESHSEG_ASSIGN_OR_RETURN(out.mesh_geometry, MeshGeometryFromProto(result.mesh_geometry(),
                                                                      result.face_labels_size()));
  }
  out.length_unit = result.length_unit();
  return out;
}

}  // namespace meshseg
