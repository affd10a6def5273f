#include "reconstruct/refine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "meshseg/remesh.h"
#include "meshseg/status_macros.h"
#include "reconstruct/crease_snap.h"
#include "reconstruct/project_to_points.h"

#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// Newton steps of x towards f = 0 along the central-difference gradient of f
// (step `delta`), each at most `max_step` long; stops where f is flat or a
// step is shorter than `tolerance`.
Eigen::Vector3d OntoZeroSet(const PuFunction& f, Eigen::Vector3d x, double delta, double max_step,
                            double tolerance) {
  for (int step = 0; step < kZeroSetIterations; ++step) {
    const double value = f(x);
    Eigen::Vector3d gradient;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = delta * Eigen::Vector3d::Unit(k);
      gradient[k] = (f(x + e) - f(x - e)) / (2.0 * delta);
    }
    const double g2 = gradient.squaredNorm();
    if (!(g2 > kMinGradient * kMinGradient)) break;
    Eigen::Vector3d move = -value / g2 * gradient;
    if (move.norm() > max_step) move *= max_step / move.norm();
    x += move;
    if (move.norm() < tolerance) break;
  }
  return x;
}

}  // namespace

absl::StatusOr<Mesh> SplitInFour(const Mesh& mesh) {
  const TriMesh& tri = mesh.tri;
  const int nv = static_cast<int>(tri.n_vertices());
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(tri.n_vertices() + tri.n_edges());
  for (const auto v : tri.vertices()) vertices.push_back(ToEigen(tri.point(v)));
  for (const auto e : tri.edges()) {
    const auto h = tri.halfedge_handle(e, 0);
    vertices.push_back(0.5 * (ToEigen(tri.point(tri.from_vertex_handle(h))) +
                              ToEigen(tri.point(tri.to_vertex_handle(h)))));
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(4 * tri.n_faces());
  for (const auto f : tri.faces()) {
    const auto h0 = tri.halfedge_handle(f);
    const auto h1 = tri.next_halfedge_handle(h0);
    const auto h2 = tri.next_halfedge_handle(h1);
    const int a = tri.from_vertex_handle(h0).idx(), b = tri.from_vertex_handle(h1).idx(),
              c = tri.from_vertex_handle(h2).idx();
    const int ab = nv + tri.edge_handle(h0).idx(), bc = nv + tri.edge_handle(h1).idx(),
              ca = nv + tri.edge_handle(h2).idx();
    triangles.push_back({a, ab, ca});
    triangles.push_back({ab, b, bc});
    triangles.push_back({ca, bc, c});
    triangles.push_back({ab, bc, ca});
  }
  return BuildMesh(std::move(vertices), triangles, mesh.name);
}

absl::StatusOr<Mesh> RefineOnPoints(const Mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<Eigen::Vector3d>& normals,
                                    const mesh_internal::PointIndex& index, const PuFunction& f,
                                    double h, const ReconstructParams& params,
                                    const RunContext& ctx, ReconstructStats* stats) {
  // An equilateral triangle of edge l has area (√3/4) l²: the edge at which
  // the surface holds refine_max_faces of them.
  const double area = Assess(mesh).surface_area;
  const double capped = std::sqrt(4.0 * area / (std::sqrt(3.0) * params.refine_max_faces));
  stats->refine_edge_length = std::max(params.refine_edge_length * h, capped);
  RemeshParams remesh;
  remesh.feature_angle_deg = 180.0;  // no feature edges, see refine.h
  remesh.small_radius_edges = 0.0;   // a staircase, not facets of a CAD surface
  // CGAL's remesher runs on one thread at a cost in proportion to its output
  // (24 s for 456K triangles); a large surface is remeshed at twice the edge
  // and split in four, which gives the same edge and count, and the
  // projection below (on all cores) puts the midpoints on the points too.
  const double faces =
      area / (std::sqrt(3.0) / 4.0 * stats->refine_edge_length * stats->refine_edge_length);
  const bool split = faces > kSerialRemeshFaces;
  MESHSEG_ASSIGN_OR_RETURN(
      Mesh fine,
      IsotropicRemesh(mesh, (split ? 2.0 : 1.0) * stats->refine_edge_length, remesh, ctx));
  // The remesher may collapse across a sheet thinner than its edges and
  // pinch it; the mesh builder then drops the faces it cannot hold. The
  // refinement must keep the closed 2-manifold, so then the marching-
  // tetrahedra mesh stays.
  for (const auto e : fine.tri.edges()) {
    if (fine.tri.is_boundary(e)) {
      stats->refine_edge_length = 0.0;
      return mesh;
    }
  }
  if (split) {
    MESHSEG_ASSIGN_OR_RETURN(fine, SplitInFour(fine));
  }
  ctx.Progress("reconstruct: projection", 0.0);
  const double radius = params.projection_radius * h;
  const std::vector<Eigen::Vector3d> no_normals;
  const bool sharp = params.sharp_creases && stats->noise <= kMaxCreaseNoise * h;
  const std::vector<Eigen::Vector3d>& crease_normals = sharp ? normals : no_normals;
  std::vector<std::pair<int, Crease>> creases;
  std::vector<uint8_t> unsupported(fine.tri.n_vertices(), 0);
  // Projects `only` (all vertices when null), vertices with no points near
  // them onto f = 0; adds the creases found.
  const auto project = [&](const std::vector<int>* only) {
    std::vector<std::pair<int, Crease>> found;
    std::vector<int> left = ProjectToPoints(points, index, radius, kProjectionIterations, &fine.tri,
                                            crease_normals, stats->noise, &found, only);
    creases.insert(creases.end(), found.begin(), found.end());
    tbb::parallel_for(size_t{0}, left.size(), [&](size_t i) {
      const TriMesh::VertexHandle v(left[i]);
      const Eigen::Vector3d x =
          OntoZeroSet(f, ToEigen(fine.tri.point(v)), 0.5 * h, radius, kZeroSetTolerance * h);
      fine.tri.set_point(v, TriMesh::Point(x[0], x[1], x[2]));
    });
    // A vertex that f = 0 brought onto the sampled surface is put on the
    // points like every other; the rest stay on f = 0. On the sampled surface
    // means: its own projection neighbourhood holds points, or a point lies
    // within one spacing h of it (no widening: in an occlusion gap the
    // nearest points are often another face's). The count alone is not
    // enough: a disc of the projection radius holds only about 15 points of
    // a uniform random sample (h is the median mean distance to several
    // neighbours, outliers.h, so (2.5 h)² π covers ~15 points, not 20),
    // close to kMinProjectionPoints; and a vertex beside a convex crease sees
    // less than a disc of surface. Vertices that f = 0 had put among the
    // points then failed the count, stayed on f = 0, and were left out of
    // the crease halving below: their faces stayed chords of the crease.
    std::vector<int> onto;
    std::vector<int> stay;
    {
      std::vector<std::pair<uint32_t, double>> near;
      for (const int v : left) {
        const Eigen::Vector3d x = ToEigen(fine.tri.point(TriMesh::VertexHandle(v)));
        index.WithinRadiusUnordered(x, radius, &near);
        const bool on_points = near.size() >= kMinProjectionPoints ||
                               (points[index.Closest(x)] - x).squaredNorm() <= h * h;
        (on_points ? onto : stay).push_back(v);
      }
    }
    if (!onto.empty()) {
      const std::vector<int> still =
          ProjectToPoints(points, index, radius, kProjectionIterations, &fine.tri, crease_normals,
                          stats->noise, &found, &onto);
      creases.insert(creases.end(), found.begin(), found.end());
      stay.insert(stay.end(), still.begin(), still.end());
    }
    left = std::move(stay);
    unsupported.resize(fine.tri.n_vertices(), 0);
    for (const int v : left) unsupported[v] = 1;
    stats->unsupported_vertex_count += static_cast<int64_t>(left.size());
  };
  project(nullptr);
  // An edge the projection stretched spans between two surfaces: vertices of
  // a chord that cut a crease (a marching-tetrahedra "tent", refine.h) went
  // onto either side of it, farther from the crease than its fits reach.
  // Its midpoint, projected, lies on the crease or on one side; halving such
  // edges a few times puts vertices along the crease where the remesher left
  // none. Only edges whose ends lie on surfaces at a crease angle (the
  // normals of their nearest points kMinCreaseAngleDeg apart): a stretch
  // along one surface (a fold, a handle) is not a crease's.
  const double cos_crease = std::cos(kMinCreaseAngleDeg * M_PI / 180.0);
  // The halving runs until no stretched edge is left. Tents are as large as
  // the supports, tens of spacings on a dense sample, so the rounds needed,
  // log2(longest / (kStretchedEdge × edge)) plus those for the new edges
  // each split makes, are set by the geometry; kStretchedRounds only bounds
  // the work. A midpoint that the projection took back towards an end of
  // its edge (nearer to it than kStuckFraction of the half edge: at a corner
  // of three planes, which the crease fit does not model) made no progress;
  // its edges are not split again, which would only add vertices off the
  // surface.
  std::vector<uint8_t> stuck(fine.tri.n_vertices(), 0);
  for (int round = 0; sharp && round < kStretchedRounds; ++round) {
    const double longest = kStretchedEdge * stats->refine_edge_length;
    std::vector<TriMesh::EdgeHandle> stretched;
    for (const auto e : fine.tri.edges()) {
      const auto he = fine.tri.halfedge_handle(e, 0);
      const auto a = fine.tri.from_vertex_handle(he), b = fine.tri.to_vertex_handle(he);
      if (unsupported[a.idx()] || unsupported[b.idx()]) continue;
      if (stuck[a.idx()] || stuck[b.idx()]) continue;
      if (!(fine.tri.calc_edge_length(e) > longest)) continue;
      const Eigen::Vector3d& na = normals[index.Closest(ToEigen(fine.tri.point(a)))];
      const Eigen::Vector3d& nb = normals[index.Closest(ToEigen(fine.tri.point(b)))];
      if (na.dot(nb) < cos_crease) stretched.push_back(e);
    }
    if (stretched.empty()) break;
    std::vector<int> added;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> ends;
    for (const auto e : stretched) {
      const auto he = fine.tri.halfedge_handle(e, 0);
      const Eigen::Vector3d pa = ToEigen(fine.tri.point(fine.tri.from_vertex_handle(he)));
      const Eigen::Vector3d pb = ToEigen(fine.tri.point(fine.tri.to_vertex_handle(he)));
      const Eigen::Vector3d mid = 0.5 * (pa + pb);
      added.push_back(fine.tri.split(e, TriMesh::Point(mid[0], mid[1], mid[2])).idx());
      ends.emplace_back(pa, pb);
    }
    stats->stretched_split_count += static_cast<int64_t>(added.size());
    project(&added);
    stuck.resize(fine.tri.n_vertices(), 0);
    for (size_t i = 0; i < added.size(); ++i) {
      const Eigen::Vector3d m = ToEigen(fine.tri.point(TriMesh::VertexHandle(added[i])));
      const double half = 0.5 * (ends[i].first - ends[i].second).norm();
      const double nearer = std::min((m - ends[i].first).norm(), (m - ends[i].second).norm());
      stuck[added[i]] = nearer < kStuckFraction * half;
    }
  }
  stats->crease_vertex_count = static_cast<int64_t>(creases.size());
  if (sharp) {
    const CreaseSnap snap = SnapToCreases(creases, &fine.tri);
    stats->crease_snapped_count = snap.moved;
    stats->crease_inserted_count = snap.inserted;
    RemoveFlatTriangles(&fine.tri);
    // Splits added faces; the refined mesh's faces are its own input faces.
    fine.face_of_input.resize(fine.tri.n_faces());
    std::iota(fine.face_of_input.begin(), fine.face_of_input.end(), 0);
  }
  fine.tri.update_normals();
  return fine;
}

}  // namespace meshseg::reconstruct_internal
