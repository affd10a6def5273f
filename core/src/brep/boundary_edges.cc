#include "brep/boundary_edges.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopoDS_Vertex.hxx>

#include "absl/strings/str_cat.h"
#include "brep/corner_clusters.h"
#include "brep/corner_points.h"
#include "brep/edge_curve.h"
#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

// True if every point of `polyline` lies within `radius` of `center`.
bool WithinOf(const std::vector<Vector3d>& polyline, const Vector3d& center, double radius) {
  for (const Vector3d& p : polyline) {
    if ((p - center).norm() > radius) return false;
  }
  return true;
}

// Grows the tolerance of `v` to reach `p`.
void Reach(const TopoDS_Vertex& v, const gp_Pnt& p) {
  const double d = BRep_Tool::Pnt(v).Distance(p);
  if (d > BRep_Tool::Tolerance(v)) {
    BRep_Builder().UpdateVertex(v, 1.001 * d + Precision::Confusion());
  }
}

// The parameter in [t.first, t.first + period) where the closed periodic
// curve `t` crosses the seam (u = 0) of `surface`, or nullopt if it does not
// cross it cleanly.
std::optional<double> SeamCrossing(const TrimmedCurve& t, const Handle(Geom_Surface) & surface) {
  constexpr int kSamples = 72;
  const double period = t.curve->Period();
  auto wrapped_u = [&](double s) -> std::optional<double> {
    const std::optional<SurfacePoint> q = ClosestPoint(surface, ToEigen(t.curve->Value(s)));
    if (!q) return std::nullopt;
    return std::remainder(q->u, 2.0 * M_PI);
  };
  std::optional<double> prev = wrapped_u(t.first);
  for (int k = 1; k <= kSamples; ++k) {
    double a = t.first + period * (k - 1) / kSamples;
    double b = t.first + period * k / kSamples;
    const std::optional<double> next = wrapped_u(b);
    if (prev && next && std::abs(*prev) < M_PI / 2 && std::abs(*next) < M_PI / 2 &&
        (*prev <= 0.0) != (*next <= 0.0)) {
      double ua = *prev;
      for (int it = 0; it < 40; ++it) {
        const double m = 0.5 * (a + b);
        const std::optional<double> um = wrapped_u(m);
        if (!um) break;
        if ((*um <= 0.0) == (ua <= 0.0)) {
          a = m;
          ua = *um;
        } else {
          b = m;
        }
      }
      return 0.5 * (a + b);
    }
    prev = next;
  }
  return std::nullopt;
}

// Two surfaces crossing at angle theta: moving one by d along its normal
// moves their intersection by d / sin(theta) across the curve (and by
// sqrt(2 r d) where they touch, theta = 0). The intersection is the edge
// only where a surface offset within the noise keeps it within the curve
// tolerance; theta is the mean angle between the normals along the curve.
bool Transversal(const BoundaryCurve& c, const EdgeTolerances& t) {
  const double theta = c.normal_angle_deg * M_PI / 180.0;
  return std::sin(std::min(theta, 0.5 * M_PI)) * t.curve > t.surface_offset;
}

const char* EdgeErrorName(BRepBuilderAPI_EdgeError e) {
  switch (e) {
    case BRepBuilderAPI_EdgeDone: return "done";
    case BRepBuilderAPI_PointProjectionFailed: return "point projection failed";
    case BRepBuilderAPI_ParameterOutOfRange: return "parameter out of range";
    case BRepBuilderAPI_DifferentPointsOnClosedCurve: return "different points on a closed curve";
    case BRepBuilderAPI_PointWithInfiniteParameter: return "point with infinite parameter";
    case BRepBuilderAPI_DifferentsPointAndParameter: return "point and parameter disagree";
    case BRepBuilderAPI_LineThroughIdenticPoints: return "line through identical points";
  }
  return "unknown error";
}

}  // namespace

BoundaryEdges MakeBoundaryEdges(const TriMesh& mesh, const Topology& topology,
                                std::span<const Handle(Geom_Surface)> surfaces,
                                const EdgeTolerances& tolerances) {
  const size_t n = topology.curves.size();
  BoundaryEdges out;
  out.edges.resize(n);
  out.failure.resize(n);
  out.contracted.assign(n, 0);
  // Corner clusters start on the common point of their surfaces.
  const CornerClusters clusters = ClusterCorners(
      mesh, topology, surfaces, std::max(tolerances.surface_offset, tolerances.exact_gap));
  std::map<int, Vector3d> position;
  for (const auto& [cluster, regions] : clusters.regions) {
    std::vector<Handle(Geom_Surface)> around;
    for (const int r : regions) around.push_back(surfaces[r]);
    position[cluster] =
        CornerPoint(clusters.start.at(cluster), around, tolerances.corner_move,
                    {.surface_offset = tolerances.surface_offset, .spacing = tolerances.l_avg});
  }
  auto cluster_of = [&](int corner) { return clusters.cluster[corner]; };

  // The request of each curve that becomes an edge.
  std::vector<std::vector<Vector3d>> polylines(n);
  std::vector<std::optional<EdgeRequest>> requests(n);
  for (const BoundaryCurve& c : topology.curves) {
    for (const int v : c.vertices) {
      polylines[c.id].push_back(meshseg::ToEigen(mesh.point(OpenMesh::VertexHandle(v))));
    }
    const bool cornered = c.start_corner >= 0 && c.end_corner >= 0;
    if (clusters.artifact[c.id] ||
        (cornered && cluster_of(c.start_corner) == cluster_of(c.end_corner) &&
         WithinOf(polylines[c.id], position[cluster_of(c.start_corner)], tolerances.curve))) {
      out.contracted[c.id] = 1;
      continue;
    }
    EdgeRequest request{.polyline = polylines[c.id],
                        .left = c.left_region,
                        .right = c.right_region,
                        .start = std::nullopt,
                        .end = std::nullopt,
                        .hint = c.geometry,
                        .tolerance = tolerances.curve,
                        .exact_gap = tolerances.exact_gap,
                        .l_avg = tolerances.l_avg,
                        .transversal = Transversal(c, tolerances),
                        .surface_offset = tolerances.surface_offset};
    // A region without a surface leaves its curves to the other side's.
    if (surfaces[request.left].IsNull()) std::swap(request.left, request.right);
    if (request.left < 0 || surfaces[request.left].IsNull()) {
      out.failure[c.id] = "neither region of the curve has a surface";
      continue;
    }
    if (request.right >= 0 && surfaces[request.right].IsNull()) request.right = -1;
    requests[c.id] = request;
  }

  IntersectionCache cache;
  std::vector<std::optional<EdgeCurve>> chosen(n);
  auto choose = [&](const BoundaryCurve& c) {
    EdgeRequest& request = *requests[c.id];
    if (c.start_corner >= 0 && c.end_corner >= 0) {
      request.start = position[cluster_of(c.start_corner)];
      request.end = position[cluster_of(c.end_corner)];
    }
    chosen[c.id] = ChooseEdgeCurve(request, surfaces, &cache);
  };
  for (const BoundaryCurve& c : topology.curves) {
    if (requests[c.id]) choose(c);
  }
  // A corner where exact edges end moves onto them (their crossing, or the
  // middle of their closest points where tangent surfaces make them touch),
  // and the edges ending there are chosen again from it.
  std::map<int, std::vector<Handle(Geom_Curve)>> exact_at;
  for (const BoundaryCurve& c : topology.curves) {
    if (!chosen[c.id] || !chosen[c.id]->exact || c.start_corner < 0) continue;
    exact_at[cluster_of(c.start_corner)].push_back(chosen[c.id]->trimmed.curve);
    if (cluster_of(c.end_corner) != cluster_of(c.start_corner)) {
      exact_at[cluster_of(c.end_corner)].push_back(chosen[c.id]->trimmed.curve);
    }
  }
  std::vector<char> moved_cluster(topology.corners.size(), 0);
  for (const auto& [cluster, curves] : exact_at) {
    if (curves.size() < 2) continue;
    const Vector3d p =
        CornerOnCurves(position[cluster], curves, tolerances.corner_move,
                       {.surface_offset = tolerances.surface_offset, .spacing = tolerances.l_avg});
    if ((p - position[cluster]).norm() > tolerances.exact_gap) {
      position[cluster] = p;
      moved_cluster[cluster] = 1;
    }
  }
  for (const BoundaryCurve& c : topology.curves) {
    if (requests[c.id] && c.start_corner >= 0 &&
        (moved_cluster[cluster_of(c.start_corner)] || moved_cluster[cluster_of(c.end_corner)])) {
      choose(c);
    }
  }

  // Clusters at one point are one vertex: a point is a vertex of the B-rep
  // (the surfaces around two clusters may meet at a single point, and both
  // corners move onto it).
  std::map<int, TopoDS_Vertex> vertices;
  std::vector<std::pair<Vector3d, TopoDS_Vertex>> made;
  for (const auto& [cluster, p] : position) {
    const auto same = std::find_if(made.begin(), made.end(), [&](const auto& m) {
      return (m.first - p).norm() <= tolerances.exact_gap;
    });
    if (same == made.end()) {
      made.emplace_back(p, BRepBuilderAPI_MakeVertex(ToPnt(p)).Vertex());
      vertices[cluster] = made.back().second;
    } else {
      vertices[cluster] = same->second;
    }
  }
  std::vector<char> full_turn(topology.regions.size(), 0);
  for (const Loop& l : topology.loops) full_turn[l.region] |= l.kind == LoopKind::kAxial;
  for (const BoundaryCurve& c : topology.curves) {
    if (!requests[c.id]) continue;
    if (!chosen[c.id]) {
      out.failure[c.id] = "no curve follows the boundary";
      continue;
    }
    TrimmedCurve t = chosen[c.id]->trimmed;
    TopoDS_Vertex v1, v2;
    if (c.start_corner >= 0) {
      v1 = vertices.at(cluster_of(c.start_corner));
      v2 = vertices.at(cluster_of(c.end_corner));
      if (cluster_of(c.start_corner) != cluster_of(c.end_corner) && v1.IsSame(v2)) {
        // A curve between two corners that became one vertex has no length
        // in the B-rep: contracted into it, as a junction artifact.
        out.contracted[c.id] = 1;
        continue;
      }
    } else {
      // A closed curve on a face that goes all the way round its axis starts
      // on that face's seam, where the seam edge will join it.
      for (const int r : {c.left_region, c.right_region}) {
        if (r < 0 || !full_turn[r] || surfaces[r].IsNull() || !surfaces[r]->IsUPeriodic() ||
            !t.curve->IsPeriodic()) {
          continue;
        }
        if (const std::optional<double> s = SeamCrossing(t, surfaces[r])) {
          t.last = *s + (t.last - t.first);
          t.first = *s;
          break;
        }
      }
      v1 = BRepBuilderAPI_MakeVertex(t.curve->Value(t.first)).Vertex();
      v2 = v1;
    }
    Reach(v1, t.curve->Value(t.first));
    Reach(v2, t.curve->Value(t.last));
    BRepBuilderAPI_MakeEdge make(t.curve, v1, v2, t.first, t.last);
    if (!make.IsDone()) {
      out.failure[c.id] = absl::StrCat("edge construction: ", EdgeErrorName(make.Error()));
      continue;
    }
    out.edges[c.id] = make.Edge();
    BRep_Builder().UpdateEdge(out.edges[c.id], std::max(t.gap, Precision::Confusion()));
    ++(chosen[c.id]->exact ? out.exact_count : out.fitted_count);
  }
  return out;
}

}  // namespace meshseg::brep_internal
