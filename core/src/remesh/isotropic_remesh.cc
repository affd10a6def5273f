// IsotropicRemesh(): CGAL's isotropic_remeshing (Botsch & Kobbelt 2004:
// split long, collapse short, flip to valence 6, tangential relaxation,
// projection onto the input) on a Surface_mesh copy of the input, with the
// input's sharp edges as constrained polylines.
#include <array>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include "absl/strings/str_cat.h"
#include "meshseg/remesh.h"
#include "meshseg/status_macros.h"

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

}  // namespace

absl::StatusOr<Mesh> IsotropicRemesh(const Mesh& mesh, double target_edge_length,
                                     const RemeshParams& params, const RunContext& ctx) {
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
  ctx.Progress("remesh", 1.0);
  sm.collect_garbage();
  return FromSurfaceMesh(sm, mesh.name);
}

}  // namespace meshseg
