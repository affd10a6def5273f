// IsotropicRemesh(): CGAL's isotropic_remeshing (Botsch & Kobbelt 2004:
// split long, collapse short, flip to valence 6, tangential relaxation,
// projection onto the input) on a Surface_mesh copy of the input, with the
// input's sharp edges as constrained polylines; then a second, finer pass
// around curved features of small radius (small_features.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include "absl/strings/str_cat.h"
#include "meshseg/remesh.h"
#include "meshseg/status_macros.h"
#include "small_features.h"

namespace meshseg {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh ToSurfaceMesh(const TriMesh& tri) {
  SurfaceMesh sm;
  sm.reserve(static_cast<SurfaceMesh::size_type>(tri.n_vertices()),
             static_cast<SurfaceMesh::size_type>(3 * tri.n_faces() / 2),
             static_cast<SurfaceMesh::size_type>(tri.n_faces()));
  std::vector<SurfaceMesh::Vertex_index> vertex(tri.n_vertices());
  for (const auto v : tri.vertices()) {
    const auto& p = tri.point(v);
    vertex[v.idx()] = sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  }
  for (const auto f : tri.faces()) {
    auto fv = tri.cfv_iter(f);
    const int a = fv->idx(), b = (++fv)->idx(), c = (++fv)->idx();
    // The input is an oriented 2-manifold (OpenMesh holds no other), so
    // Surface_mesh takes every face.
    sm.add_face(vertex[a], vertex[b], vertex[c]);
  }
  return sm;
}

absl::StatusOr<Mesh> FromSurfaceMesh(const SurfaceMesh& sm, const std::string& name) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(sm.number_of_vertices());
  std::vector<int> index(sm.num_vertices(), -1);  // garbage-aware: by Vertex_index
  for (const auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    index[v] = static_cast<int>(points.size());
    points.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(sm.number_of_faces());
  for (const auto f : sm.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) t[k] = index[v];
      ++k;
    }
    if (k != 3) return absl::InternalError(absl::StrCat(name, ": remeshed face with ", k, " corners"));
    triangles.push_back(t);
  }
  return BuildMesh(std::move(points), triangles, name);
}

using FaceTree =
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;
using Segments = std::vector<Kernel::Segment_3>;
using SegmentTree = CGAL::AABB_tree<
    CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segments::const_iterator>>>;

// Moves a vertex of the mesh being remeshed to the closest point of the
// input surface (CGAL's own projection would use the first pass's chords).
class ProjectOnInput {
 public:
  ProjectOnInput(const SurfaceMesh& mesh, const FaceTree& input) : mesh_(mesh), input_(input) {}
  Kernel::Point_3 operator()(SurfaceMesh::Vertex_index v) const {
    return input_.closest_point(mesh_.point(v));
  }

 private:
  const SurfaceMesh& mesh_;
  const FaceTree& input_;
};

Kernel::Point_3 ToPoint(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// The faces of `sm` with a corner within `margin` of one of `near`'s
// segments, and their area. Each vertex is asked once.
std::vector<SurfaceMesh::Face_index> FacesNear(const SurfaceMesh& sm, const SegmentTree& near,
                                               double margin, double* area) {
  std::vector<bool> is_near(sm.num_vertices(), false);  // by Vertex_index
  for (const auto v : sm.vertices()) {
    is_near[v] = near.squared_distance(sm.point(v)) <= margin * margin;
  }
  std::vector<SurfaceMesh::Face_index> zone;
  *area = 0.0;
  for (const auto f : sm.faces()) {
    const auto corners = CGAL::vertices_around_face(sm.halfedge(f), sm);
    if (std::any_of(corners.begin(), corners.end(), [&](auto v) { return is_near[v]; })) {
      zone.push_back(f);
      *area += PMP::face_area(f, sm);
    }
  }
  return zone;
}

// Second pass: the faces of `sm` within kZoneMargin target edges of an input
// edge of small radius (small_features.h) are remeshed at that radius over
// fine_edges_per_radius, projected onto the input itself. The radius is the
// 5th percentile of the edges' estimates (the smallest feature, not a stray
// edge); the length is at least target / kMaxRefinement and keeps the zone
// under kFineFaceShare of the face budget (CGAL's edges come out ~10 %
// shorter than asked, so the total stays under 1.5 budgets).
void RefineSmallFeatures(const Mesh& mesh, double target_edge_length, const RemeshParams& params,
                         SurfaceMesh& sm,
                         SurfaceMesh::Property_map<SurfaceMesh::Edge_index, bool> is_feature,
                         RemeshStats* stats) {
  const std::vector<remesh_internal::CurvedEdge> small = remesh_internal::SmallRadiusEdges(
      mesh.tri, params.small_radius_edges * target_edge_length, params.feature_angle_deg);
  if (small.empty()) return;
  std::vector<double> radii;
  Segments segments;
  for (const auto& e : small) {
    radii.push_back(e.radius);
    segments.emplace_back(ToPoint(e.a), ToPoint(e.b));
  }
  auto p5 = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 20);
  std::nth_element(radii.begin(), p5, radii.end());
  stats->small_feature_radius = *p5;

  SegmentTree near(segments.begin(), segments.end());
  near.accelerate_distance_queries();
  const double margin = kZoneMargin * target_edge_length;
  double zone_area = 0.0;
  const std::vector<SurfaceMesh::Face_index> zone = FacesNear(sm, near, margin, &zone_area);
  const double budget = kFineFaceShare * static_cast<double>(params.max_faces);
  // An equilateral triangle of side L has area sqrt(3)/4 L^2.
  const double fine = std::max({*p5 / params.fine_edges_per_radius,
                                target_edge_length / kMaxRefinement,
                                std::sqrt(4.0 * zone_area / (std::sqrt(3.0) * budget))});
  if (fine > target_edge_length / kMinRefinement) return;
  stats->fine_edge_length = fine;

  SurfaceMesh input = ToSurfaceMesh(mesh.tri);
  FaceTree on_input(faces(input).first, faces(input).second, input);
  on_input.accelerate_distance_queries();
  PMP::isotropic_remeshing(zone, fine, sm,
                           PMP::parameters::number_of_iterations(std::max(1, params.iterations))
                               .edge_is_constrained_map(is_feature)
                               .projection_functor(ProjectOnInput(sm, on_input)));
  // The remesher does not project constrained vertices (feature lines, the
  // zone's border): those it made sit on the first pass's chords.
  const double reach = 2.0 * margin;
  for (const auto v : sm.vertices()) {
    if (near.squared_distance(sm.point(v)) <= reach * reach) {
      sm.point(v) = on_input.closest_point(sm.point(v));
    }
  }
}

}  // namespace

absl::StatusOr<Mesh> IsotropicRemesh(const Mesh& mesh, double target_edge_length,
                                     const RemeshParams& params, const RunContext& ctx,
                                     RemeshStats* stats) {
  RemeshStats unused;
  if (stats == nullptr) stats = &unused;
  *stats = {};
  if (!(target_edge_length > 0.0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "remesh ", mesh.name, ": target edge length must be positive, got ", target_edge_length));
  }
  if (mesh.tri.n_faces() == 0) {
    return absl::InvalidArgumentError(absl::StrCat("remesh ", mesh.name, ": mesh has no faces"));
  }
  ctx.Progress("remesh", 0.0);
  SurfaceMesh sm = ToSurfaceMesh(mesh.tri);
  auto is_feature = sm.add_property_map<SurfaceMesh::Edge_index, bool>("e:feature", false).first;
  PMP::detect_sharp_edges(sm, params.feature_angle_deg, is_feature);
  // All rounds in one call: each call projects onto its own input, so
  // round-by-round calls would project onto the previous round's chords and
  // drift off the input surface (0.03 on a r = 10 cylinder). A stop is
  // therefore seen before and after, not during, the remeshing.
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("remesh"));
  PMP::isotropic_remeshing(faces(sm), target_edge_length, sm,
                           PMP::parameters::number_of_iterations(std::max(1, params.iterations))
                               .edge_is_constrained_map(is_feature));
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("remesh"));
  if (params.small_radius_edges > 0.0) {
    RefineSmallFeatures(mesh, target_edge_length, params, sm, is_feature, stats);
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("remesh"));
  }
  ctx.Progress("remesh", 1.0);
  sm.collect_garbage();
  return FromSurfaceMesh(sm, mesh.name);
}

}  // namespace meshseg
