// Topology and features of a PipelineResult into a SegmentationResult.
#include "proto/src/topology_to_proto.h"

namespace meshseg {

void SetVec3(const Eigen::Vector3d& v, v1::Vec3* out) {
  out->set_x(v.x());
  out->set_y(v.y());
  out->set_z(v.z());
}

namespace {

v1::CurveGeometryType ToProto(CurveGeometryType type) {
  switch (type) {
    case CurveGeometryType::kPolyline: return v1::CURVE_GEOMETRY_TYPE_POLYLINE;
    case CurveGeometryType::kLine: return v1::CURVE_GEOMETRY_TYPE_LINE;
    case CurveGeometryType::kCircle: return v1::CURVE_GEOMETRY_TYPE_CIRCLE;
  }
  return v1::CURVE_GEOMETRY_TYPE_UNSPECIFIED;
}

v1::CurveConvexity ToProto(CurveConvexity convexity) {
  switch (convexity) {
    case CurveConvexity::kConvex: return v1::CURVE_CONVEXITY_CONVEX;
    case CurveConvexity::kConcave: return v1::CURVE_CONVEXITY_CONCAVE;
    case CurveConvexity::kBorder: return v1::CURVE_CONVEXITY_BORDER;
  }
  return v1::CURVE_CONVEXITY_UNSPECIFIED;
}

v1::LoopKind ToProto(LoopKind kind) {
  switch (kind) {
    case LoopKind::kOuter: return v1::LOOP_KIND_OUTER;
    case LoopKind::kInner: return v1::LOOP_KIND_INNER;
    case LoopKind::kAxial: return v1::LOOP_KIND_AXIAL;
  }
  return v1::LOOP_KIND_UNSPECIFIED;
}

v1::FeatureType ToProto(FeatureType type) {
  switch (type) {
    case FeatureType::kFilletTorusSpherePlane: return v1::FEATURE_TYPE_FILLET_TORUS_SPHERE_PLANE;
    case FeatureType::kFilletTorusCylinderPlane:
      return v1::FEATURE_TYPE_FILLET_TORUS_CYLINDER_PLANE;
    case FeatureType::kFilletCylinderPlanes: return v1::FEATURE_TYPE_FILLET_CYLINDER_PLANES;
    case FeatureType::kCornerBlendSphere: return v1::FEATURE_TYPE_CORNER_BLEND_SPHERE;
    case FeatureType::kCornerBlendTorus: return v1::FEATURE_TYPE_CORNER_BLEND_TORUS;
    case FeatureType::kLinearExtrusion: return v1::FEATURE_TYPE_LINEAR_EXTRUSION;
    case FeatureType::kRevolution: return v1::FEATURE_TYPE_REVOLUTION;
  }
  return v1::FEATURE_TYPE_UNSPECIFIED;
}

void SetCurve(const BoundaryCurve& c, v1::BoundaryCurve* out) {
  out->set_id(c.id);
  out->mutable_vertices()->Add(c.vertices.begin(), c.vertices.end());
  out->set_left_region(c.left_region);
  out->set_right_region(c.right_region);
  out->set_closed(c.closed);
  out->set_start_corner(c.start_corner);
  out->set_end_corner(c.end_corner);
  out->set_normal_angle_deg(c.normal_angle_deg);
  out->set_sharp(c.sharp);
  out->set_convexity(ToProto(c.convexity));
  v1::CurveGeometry* g = out->mutable_geometry();
  g->set_type(ToProto(c.geometry.type));
  SetVec3(c.geometry.point, g->mutable_point());
  SetVec3(c.geometry.direction, g->mutable_direction());
  g->set_radius(c.geometry.radius);
  g->set_analytic(c.geometry.analytic);
  g->set_max_deviation(c.geometry.max_deviation);
  out->set_length(c.length);
  out->set_junction_artifact(c.junction_artifact);
}

void SetLoop(const Loop& l, v1::Loop* out) {
  out->set_id(l.id);
  out->set_region(l.region);
  out->set_patch(l.patch);
  out->set_kind(ToProto(l.kind));
  for (const CurveUse& use : l.curves) {
    v1::CurveUse* u = out->add_curves();
    u->set_curve(use.curve);
    u->set_reversed(use.reversed);
  }
}

void SetCorner(const Corner& c, v1::Corner* out) {
  out->set_id(c.id);
  out->set_vertex(c.vertex);
  out->set_cluster(c.cluster);
  SetVec3(c.position, out->mutable_position());
  out->set_snapped(c.snapped);
  out->mutable_regions()->Add(c.regions.begin(), c.regions.end());
  out->mutable_curves()->Add(c.curves.begin(), c.curves.end());
}

void SetFeature(const Feature& f, v1::Feature* out) {
  out->set_id(f.id);
  out->set_type(ToProto(f.type));
  out->mutable_regions()->Add(f.regions.begin(), f.regions.end());
  out->set_radius(f.radius);
  out->set_convex(f.convex);
  out->set_opening_angle_deg(f.opening_angle_deg);
  SetVec3(f.direction, out->mutable_direction());
  SetVec3(f.point, out->mutable_point());
}

}  // namespace

void SetTopology(const Topology& topology, std::span<const Feature> features,
                 v1::SegmentationResult* out) {
  for (const BoundaryCurve& c : topology.curves) SetCurve(c, out->add_curves());
  for (const Loop& l : topology.loops) SetLoop(l, out->add_loops());
  for (const Corner& c : topology.corners) SetCorner(c, out->add_corners());
  for (const Adjacency& a : topology.adjacency) {
    v1::Adjacency* arc = out->add_adjacency();
    arc->set_region_a(a.region_a);
    arc->set_region_b(a.region_b);
    arc->mutable_curves()->Add(a.curves.begin(), a.curves.end());
  }
  for (const Feature& f : features) SetFeature(f, out->add_features());
}

}  // namespace meshseg
