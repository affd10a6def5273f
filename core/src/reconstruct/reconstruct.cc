#include "meshseg/reconstruct.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/cover.h"
#include "reconstruct/graph_cut.h"
#include "reconstruct/handles.h"
#include "reconstruct/marching_tetrahedra.h"
#include "reconstruct/neighbors.h"
#include "reconstruct/normals.h"
#include "reconstruct/octree.h"
#include "reconstruct/outliers.h"
#include "mesh/point_index.h"
#include "reconstruct/pu_function.h"
#include "reconstruct/refine.h"
#include "reconstruct/regular_triangulation.h"
#include "reconstruct/severed_solid.h"
#include "reconstruct/small_components.h"
#include "reconstruct/smoothing.h"
#include "reconstruct/support.h"
#include "reconstruct/surface_mesh.h"

namespace meshseg {
namespace {

using namespace reconstruct_internal;  // NOLINT: this file strings the steps together

constexpr char kStage[] = "reconstruct";
constexpr size_t kMinPoints = 20;
// Margin of the octree cube around the points' bounding box, per side, as a
// fraction of its largest extent: room for outside supports around the part.
constexpr double kCubeMargin = 0.1;
// Octree depth used when it is derived from the point spacing.
constexpr int kMinDerivedLevel = 3;
constexpr int kMaxDerivedLevel = 12;
// Two sheets of the surface nearer than this many point spacings are not
// resolved by the points (two samples across a feature, Nyquist).
constexpr double kResolvedSpacings = 2.0;

absl::Status ValidateParams(const ReconstructParams& p) {
  const auto bad = [](const std::string& what) {
    return absl::InvalidArgumentError(absl::StrCat(kStage, ": ", what));
  };
  if (!(p.error_tolerance > 0)) {
    return bad(absl::StrCat("error_tolerance ", p.error_tolerance, " must be > 0"));
  }
  if (p.octree_max_level && (*p.octree_max_level < 1 || *p.octree_max_level > kMaxOctreeLevel)) {
    return bad(absl::StrCat("octree_max_level ", *p.octree_max_level, " outside [1, ",
                            kMaxOctreeLevel, "]"));
  }
  if (!(p.leaf_cell_size > 0)) {
    return bad(absl::StrCat("leaf_cell_size ", p.leaf_cell_size, " must be > 0"));
  }
  if (!(p.graph_cut_k > 0)) return bad(absl::StrCat("graph_cut_k ", p.graph_cut_k, " must be > 0"));
  if (!(p.smoothing_lambda >= 0 && p.smoothing_lambda <= 1)) {
    return bad(absl::StrCat("smoothing_lambda ", p.smoothing_lambda, " outside [0, 1]"));
  }
  if (p.smoothing_iterations < 0) {
    return bad(absl::StrCat("smoothing_iterations ", p.smoothing_iterations, " must be >= 0"));
  }
  if (p.normal_neighbors < 3) {
    return bad(absl::StrCat("normal_neighbors ", p.normal_neighbors, " must be >= 3"));
  }
  if (!(p.min_component_fraction >= 0 && p.min_component_fraction <= 1)) {
    return bad(
        absl::StrCat("min_component_fraction ", p.min_component_fraction, " outside [0, 1]"));
  }
  if (!(p.refine_edge_length >= 0)) {
    return bad(absl::StrCat("refine_edge_length ", p.refine_edge_length, " must be >= 0"));
  }
  if (p.refine_max_faces <= 0) {
    return bad(absl::StrCat("refine_max_faces ", p.refine_max_faces, " must be > 0"));
  }
  if (!(p.projection_radius > 0)) {
    return bad(absl::StrCat("projection_radius ", p.projection_radius, " must be > 0"));
  }
  if (!(p.outlier_distance > 0)) {
    return bad(absl::StrCat("outlier_distance ", p.outlier_distance, " must be > 0"));
  }
  if (!(p.off_surface_distance > 0)) {
    return bad(absl::StrCat("off_surface_distance ", p.off_surface_distance, " must be > 0"));
  }
  if (!(p.support_spacings >= 0)) {
    return bad(absl::StrCat("support_spacings ", p.support_spacings, " must be >= 0"));
  }
  if (!(p.handle_spacings >= 0)) {
    return bad(absl::StrCat("handle_spacings ", p.handle_spacings, " must be >= 0"));
  }
  if (!(p.outlier_noise_sigmas > 0)) {
    return bad(absl::StrCat("outlier_noise_sigmas ", p.outlier_noise_sigmas, " must be > 0"));
  }
  return absl::OkStatus();
}

absl::Status ValidateCloud(const PointCloud& cloud) {
  const std::string name =
      cloud.name.empty() ? "point cloud" : absl::StrCat("\"", cloud.name, "\"");
  if (cloud.points.size() < kMinPoints) {
    return absl::InvalidArgumentError(absl::StrCat(kStage, ": ", name, ": ", cloud.points.size(),
                                                   " points, need at least ", kMinPoints));
  }
  if (cloud.has_normals() && cloud.normals.size() != cloud.points.size()) {
    return absl::InvalidArgumentError(absl::StrCat(kStage, ": ", name, ": ", cloud.normals.size(),
                                                   " normals for ", cloud.points.size(),
                                                   " points"));
  }
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (!cloud.points[i].allFinite()) {
      return absl::InvalidArgumentError(
          absl::StrCat(kStage, ": ", name, ": point ", i, " has a NaN or infinite coordinate"));
    }
    if (cloud.has_normals() && !(cloud.normals[i].allFinite() && cloud.normals[i].norm() > 0)) {
      return absl::InvalidArgumentError(
          absl::StrCat(kStage, ": ", name, ": normal ", i, " is NaN, infinite or zero"));
    }
  }
  return absl::OkStatus();
}

// The error for points that enclose no volume the octree resolves.
absl::Status ThinSolidError(const std::string& name, const std::string& what, double cell) {
  return absl::InvalidArgumentError(
      absl::StrCat(kStage, ": \"", name, "\": ", what,
                   " supports; the points enclose no volume at least two octree leaf cells (", cell,
                   " model units) thick; a thinner solid needs a smaller leaf_cell_size"));
}

// Evaluates f at every point of `at`, in parallel.
std::vector<double> Evaluate(const PuFunction& f, const std::vector<Eigen::Vector3d>& at) {
  std::vector<double> values(at.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, at.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) values[i] = f(at[i]);
  });
  return values;
}

}  // namespace

absl::StatusOr<Reconstruction> Reconstruct(const PointCloud& cloud, const ReconstructParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(ValidateCloud(cloud));
  Reconstruction out;
  ReconstructStats& stats = out.stats;
  NeighborTable all_nearest;
  {
    ctx.Progress("reconstruct: outliers", 0.0);
    const mesh_internal::PointIndex all_index(cloud.points);
    Outliers outliers = OutliersOfCloud(cloud.points, cloud.normals, all_index, params);
    stats.point_spacing = outliers.spacing;
    stats.noise = outliers.noise;
    out.is_outlier = std::move(outliers.flags);
    all_nearest = std::move(outliers.nearest);
  }
  const double h = stats.point_spacing;
  // Outliers take no part in the fits.
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> given_normals;
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    stats.outlier_count += out.is_outlier[i];
    if (out.is_outlier[i]) continue;
    points.push_back(cloud.points[i]);
    if (cloud.has_normals()) given_normals.push_back(cloud.normals[i]);
  }
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).maxCoeff();
  if (!(h > 1e-9 * extent) || !(extent > 0)) {
    return absl::InvalidArgumentError(absl::StrCat(kStage, ": \"", cloud.name, "\": points span ",
                                                   extent, " with spacing ", h,
                                                   "; they (nearly) coincide"));
  }
  const mesh_internal::PointIndex index(points);
  ctx.Progress(kStage, 0.05);

  // Step 1: inward normals, from the outlier test's neighbours.
  ctx.Progress("reconstruct: normals", 0.0);
  NeighborTable nearest = KeptNeighbors(all_nearest, out.is_outlier, points, index);
  all_nearest = {};
  if (nearest.k != params.normal_neighbors) {
    nearest = FirstColumns(nearest, params.normal_neighbors);
  }
  MESHSEG_ASSIGN_OR_RETURN(const OrientedNormals normals,
                           InwardNormals(points, given_normals, nearest, ctx));
  nearest = {};
  stats.normals_estimated = !cloud.has_normals();
  stats.normals_flipped = cloud.has_normals() && normals.flipped;
  ctx.Progress(kStage, 0.15);

  // Step 2: octree, covering and the partition-of-unity implicit f.
  const double cube = extent * (1.0 + 2.0 * kCubeMargin);
  const Eigen::Vector3d origin = 0.5 * (lo + hi) - Eigen::Vector3d::Constant(0.5 * cube);
  ctx.Progress("reconstruct: octree", 0.0);
  stats.octree_max_level = params.octree_max_level.value_or(
      std::clamp(static_cast<int>(std::ceil(std::log2(cube / (params.leaf_cell_size * h)))),
                 kMinDerivedLevel, kMaxDerivedLevel));
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<OctreeLeaf> leaves,
                           BalancedOctreeLeaves(points, origin, cube, stats.octree_max_level, ctx));
  stats.octree_leaf_count = static_cast<int64_t>(leaves.size());
  const FitInput fit_input{points, normals.normals, index, params.error_tolerance * h,
                           std::sqrt(3.0) * cube};
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<Support> supports,
                           CoverBySupports(leaves, fit_input, params.seed, ctx));
  stats.support_count = static_cast<int64_t>(supports.size());
  const PuFunction f(supports);
  // Tet vertices: the covering's centres and its inner supports' (cover.h),
  // which sample f without being terms of it, weighted to hide no centre of
  // the covering.
  std::vector<Support> vertices = supports;
  {
    const std::vector<Support> inner = InnerSupports(supports, fit_input, h);
    vertices.insert(vertices.end(), inner.begin(), inner.end());
  }
  const std::vector<double> covering_weight = RadiiSquared(supports);
  ctx.Progress(kStage, 0.4);

  // Step 3: regular tetrahedralization of the support centres.
  ctx.Progress("reconstruct: tetrahedra", 0.0);
  if (supports.size() < 4) {
    // Linear fits within ε over the whole cloud: it is (nearly) flat.
    return ThinSolidError(cloud.name, absl::StrCat("the covering has only ", supports.size()),
                          cube / (1 << stats.octree_max_level));
  }
  MESHSEG_ASSIGN_OR_RETURN(
      TetMesh tets,
      RegularTetrahedralization(vertices, TetWeights(vertices, covering_weight), ctx));
  {
    // Hull centres tied outside against the f > 0 their points read hide
    // nothing (cover.h): the tets again with their weight 0.
    const std::vector<double> hull_weight =
        CoveringWeights(supports, tets, f, params.sparse_support_points, fit_input);
    if (hull_weight != covering_weight) {
      MESHSEG_ASSIGN_OR_RETURN(
          tets, RegularTetrahedralization(vertices, TetWeights(vertices, hull_weight), ctx));
    }
  }
  stats.tet_vertex_count = static_cast<int64_t>(tets.support.size());
  stats.tet_count = static_cast<int64_t>(tets.tets.size());
  std::vector<Eigen::Vector3d> position(tets.support.size());
  std::vector<uint8_t> sparse(tets.support.size());
  for (size_t v = 0; v < tets.support.size(); ++v) {
    const Support& s = vertices[tets.support[v]];
    position[v] = s.center;
    sparse[v] = s.point_count < params.sparse_support_points;
  }
  const std::vector<double> f_at = Evaluate(f, position);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  ctx.Progress(kStage, 0.6);

  // Step 4: inside/outside labels.
  ctx.Progress("reconstruct: labels", 0.0);
  const std::vector<uint8_t> by_sign = SignLabels(tets, f_at);
  std::vector<uint8_t> inside = by_sign;
  if (params.use_graph_cut) {
    // The cut decides only where the points leave the side open (graph_cut.h).
    const std::vector<uint8_t> resolved = ResolvedInside(tets, f_at, sparse, fit_input.epsilon);
    // ... and f > 0 is no evidence of solid where the points see the vertex
    // from outside (graph_cut.h).
    const std::vector<uint8_t> seen_outside = SeenFromOutside(tets, vertices, f_at, fit_input);
    MESHSEG_ASSIGN_OR_RETURN(inside, GraphCutLabels(tets, position, f_at, params.graph_cut_k,
                                                    resolved, seen_outside, ctx));
    // ... and it does not split the solid f holds together (severed_solid.h).
    RejoinSeveredSolid(tets, f_at, by_sign, sparse, seen_outside, resolved, fit_input.epsilon,
                       &inside);
  }
  for (size_t v = 0; v < inside.size(); ++v) stats.relabelled_count += inside[v] != by_sign[v];
  ctx.Progress(kStage, 0.75);

  // Steps 5-6: marching tetrahedra and selective smoothing.
  ctx.Progress("reconstruct: surface", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(IsoSurface surface,
                           MarchingTetrahedra(tets, position, f_at, inside, sparse, f, ctx));
  if (surface.triangles.empty()) {
    return ThinSolidError(cloud.name,
                          absl::StrCat("no inside region found among ", tets.support.size()),
                          cube / (1 << stats.octree_max_level));
  }
  // A component thinner than two spacings is one sheet of points seen as
  // two (small_components.h); 0 keeps all, as the fraction.
  const double min_thickness =
      params.min_component_fraction > 0 ? kResolvedSpacings * h : 0.0;
  stats.dropped_component_count =
      DropSmallComponents(params.min_component_fraction, min_thickness, &surface);
  for (const uint8_t s : surface.to_smooth) stats.smoothed_vertex_count += s;
  SmoothSelected(surface.triangles, surface.to_smooth, params.smoothing_lambda,
                 params.smoothing_iterations, &surface.vertices);
  ctx.Progress(kStage, 0.9);
  MESHSEG_ASSIGN_OR_RETURN(out.mesh, SurfaceMesh(surface.vertices, surface.triangles, cloud.name));

  // Step 7 (our addition): a finer, scan-like mesh on the points.
  if (params.refine_edge_length > 0) {
    MESHSEG_ASSIGN_OR_RETURN(out.mesh, RefineOnPoints(out.mesh, points, normals.normals, index, f,
                                                      h, params, ctx, &stats));
  }

  // Step 8 (our addition, issue 38): no surface where no point supports it.
  out.is_filled.assign(out.mesh.tri.n_faces(), 0);
  stats.genus = stats.genus_before_support = Genus(out.mesh.tri);
  if (params.support_spacings > 0) {
    ctx.Progress("reconstruct: support", 0.0);
    const double band =
        std::max(params.off_surface_distance * h, params.outlier_noise_sigmas * stats.noise);
    // The refinement leaves no edge over kStretchedEdge refined lengths
    // unless it is a tent (refine.h); faces up to that may chord the surface.
    const std::vector<uint8_t> supported =
        SupportedFaces(out.mesh.tri, points, index, params.support_spacings, band,
                       kStretchedEdge * stats.refine_edge_length);
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    MESHSEG_ASSIGN_OR_RETURN(ClosedSurface closed,
                             CloseUnsupported(out.mesh, supported, params.min_component_fraction,
                                              params.leave_unsupported_open, {},
                                              /*bend_onto_seen_planes=*/true,
                                              /*min_tube_rim=*/M_PI * params.handle_spacings * h));
    stats.unsupported_face_count = closed.removed_face_count;
    stats.hole_count = closed.hole_count;
    stats.filled_area = closed.filled_area;
    for (const uint8_t f : closed.filled) stats.filled_face_count += f;
    out.mesh = std::move(closed.mesh);
    out.is_filled = std::move(closed.filled);
    stats.genus = Genus(out.mesh.tri);
  }

  // Step 9 (our addition, issue 38): no handle the points do not resolve.
  if (params.handle_spacings > 0 && stats.genus > 0) {
    ctx.Progress("reconstruct: handles", 0.0);
    MESHSEG_RETURN_IF_ERROR(
        CutUnsupportedHandles(points, index, params, &out.mesh, &out.is_filled, &stats));
    stats.genus = Genus(out.mesh.tri);
  }

  ctx.Progress(kStage, 1.0);
  return out;
}

}  // namespace meshseg
