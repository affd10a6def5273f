// The topology of a SegmentationResult back into a core Topology.
#include "proto/src/topology_from_proto.h"

#include <algorithm>
#include <string>

#include "absl/strings/str_cat.h"

namespace meshseg {
namespace {

absl::Status Bad(const std::string& what) {
  return absl::InvalidArgumentError(absl::StrCat("result topology: ", what));
}

absl::StatusOr<CurveGeometryType> FromProto(v1::CurveGeometryType t, int curve) {
  switch (t) {
    case v1::CURVE_GEOMETRY_TYPE_POLYLINE: return CurveGeometryType::kPolyline;
    case v1::CURVE_GEOMETRY_TYPE_LINE: return CurveGeometryType::kLine;
    case v1::CURVE_GEOMETRY_TYPE_CIRCLE: return CurveGeometryType::kCircle;
    default: return Bad(absl::StrCat("curve ", curve, " has no geometry type"));
  }
}

CurveConvexity FromProto(v1::CurveConvexity c) {
  switch (c) {
    case v1::CURVE_CONVEXITY_CONVEX: return CurveConvexity::kConvex;
    case v1::CURVE_CONVEXITY_CONCAVE: return CurveConvexity::kConcave;
    default: return CurveConvexity::kBorder;
  }
}

absl::StatusOr<LoopKind> FromProto(v1::LoopKind k, int loop) {
  switch (k) {
    case v1::LOOP_KIND_OUTER: return LoopKind::kOuter;
    case v1::LOOP_KIND_INNER: return LoopKind::kInner;
    case v1::LOOP_KIND_AXIAL: return LoopKind::kAxial;
    default: return Bad(absl::StrCat("loop ", loop, " has no kind"));
  }
}

}  // namespace

absl::StatusOr<Topology> TopologyFromProto(const v1::SegmentationResult& result) {
  Topology topo;
  const int regions = result.regions_size();
  const int curves = result.curves_size();
  const int corners = result.corners_size();
  auto region_ok = [&](int r, bool border) { return r >= (border ? -1 : 0) && r < regions; };
  auto corner_ok = [&](int c) { return c >= -1 && c < corners; };
  for (int k = 0; k < curves; ++k) {
    const v1::BoundaryCurve& m = result.curves(k);
    if (m.id() != k) return Bad(absl::StrCat("curve ", k, " has id ", m.id()));
    if (!region_ok(m.left_region(), false) || !region_ok(m.right_region(), true) ||
        !corner_ok(m.start_corner()) || !corner_ok(m.end_corner())) {
      return Bad(absl::StrCat("curve ", k, " names a region or corner that does not exist"));
    }
    BoundaryCurve c;
    c.id = k;
    c.vertices.assign(m.vertices().begin(), m.vertices().end());
    c.left_region = m.left_region();
    c.right_region = m.right_region();
    c.closed = m.closed();
    c.start_corner = m.start_corner();
    c.end_corner = m.end_corner();
    c.normal_angle_deg = m.normal_angle_deg();
    c.sharp = m.sharp();
    c.convexity = FromProto(m.convexity());
    auto type = FromProto(m.geometry().type(), k);
    if (!type.ok()) return type.status();
    c.geometry.type = *type;
    c.geometry.point = FromProto(m.geometry().point());
    c.geometry.direction = FromProto(m.geometry().direction());
    c.geometry.radius = m.geometry().radius();
    c.geometry.analytic = m.geometry().analytic();
    c.geometry.max_deviation = m.geometry().max_deviation();
    c.length = m.length();
    c.junction_artifact = m.junction_artifact();
    topo.curves.push_back(std::move(c));
  }
  topo.regions.resize(regions);
  for (int k = 0; k < regions; ++k) {
    topo.regions[k].region = k;
    topo.regions[k].patch_count = result.regions(k).face_count() > 0 ? 1 : 0;
  }
  for (int k = 0; k < result.loops_size(); ++k) {
    const v1::Loop& m = result.loops(k);
    if (m.id() != k) return Bad(absl::StrCat("loop ", k, " has id ", m.id()));
    if (!region_ok(m.region(), false) || m.patch() < 0) {
      return Bad(absl::StrCat("loop ", k, " has region ", m.region(), " patch ", m.patch()));
    }
    Loop l;
    l.id = k;
    l.region = m.region();
    l.patch = m.patch();
    auto kind = FromProto(m.kind(), k);
    if (!kind.ok()) return kind.status();
    l.kind = *kind;
    for (const v1::CurveUse& u : m.curves()) {
      if (u.curve() < 0 || u.curve() >= curves) {
        return Bad(absl::StrCat("loop ", k, " uses curve ", u.curve(), " of ", curves));
      }
      l.curves.push_back({u.curve(), u.reversed()});
    }
    RegionTopology& rt = topo.regions[l.region];
    rt.patch_count = std::max(rt.patch_count, l.patch + 1);
    rt.loops.push_back(k);
    topo.loops.push_back(std::move(l));
  }
  for (int k = 0; k < corners; ++k) {
    const v1::Corner& m = result.corners(k);
    if (m.id() != k || m.cluster() < 0 || m.cluster() >= corners) {
      return Bad(absl::StrCat("corner ", k, " has id ", m.id(), " cluster ", m.cluster()));
    }
    Corner c;
    c.id = k;
    c.vertex = m.vertex();
    c.cluster = m.cluster();
    c.position = FromProto(m.position());
    c.snapped = m.snapped();
    for (const int r : m.regions()) {
      if (!region_ok(r, true)) return Bad(absl::StrCat("corner ", k, " touches region ", r));
      c.regions.push_back(r);
    }
    for (const int cu : m.curves()) {
      if (cu < 0 || cu >= curves) return Bad(absl::StrCat("corner ", k, " ends curve ", cu));
      c.curves.push_back(cu);
    }
    topo.corners.push_back(std::move(c));
  }
  for (const v1::Adjacency& a : result.adjacency()) {
    if (!region_ok(a.region_a(), false) || !region_ok(a.region_b(), false)) {
      return Bad(absl::StrCat("adjacency of regions ", a.region_a(), " and ", a.region_b()));
    }
    topo.adjacency.push_back({a.region_a(), a.region_b(), {a.curves().begin(), a.curves().end()}});
  }
  topo.mean_edge_length = result.mesh().mean_edge_length();
  return topo;
}

}  // namespace meshseg
