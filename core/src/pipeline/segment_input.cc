// How each kind of surface is segmented into a PipelineResult: a scan as
// read, an exact tessellation facet by facet, a CAD tessellation on its
// isotropic remesh, a binary-occupancy surface de-terraced (ALGORITHMS.md S4), and a
// reconstruction with its regions refitted to the cloud's points.
#include "pipeline/segment_input.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>

#include "meshseg/fit.h"
#include "meshseg/status_macros.h"
#include "pipeline/binary_types.h"
#include "pipeline/point_labels.h"
#include "pipeline/refit_regions.h"
#include "pipeline/remeshed_labels.h"
#include "pipeline/retype_beside_neighbours.h"
#include "pipeline/separating_planes.h"

namespace meshseg::pipeline_internal {
namespace {

// A CAD export's vertices lie on their surfaces to rounding: a face whose
// corners miss its region's refitted surface by more than this, in l_avg of
// the input, may belong next door.
constexpr double kExactCorner = 1e-4;

// SegmentParams::measured of a reconstruction: a vertex is measured iff one
// of its faces is not a filled one (Reconstruction::is_filled), i.e. input
// points support some face at it; a vertex all of whose faces close an
// unscanned area lies where the patch's fairing put it. Empty (every vertex
// measured) when no face is filled.
std::vector<uint8_t> MeasuredMask(const TriMesh& mesh, std::span<const uint8_t> is_filled) {
  if (is_filled.size() != mesh.n_faces() ||
      std::none_of(is_filled.begin(), is_filled.end(), [](uint8_t f) { return f != 0; })) {
    return {};
  }
  std::vector<uint8_t> measured(mesh.n_vertices(), 0);
  for (const auto fh : mesh.faces()) {
    if (is_filled[fh.idx()]) continue;
    for (auto it = mesh.cfv_iter(fh); it.is_valid(); ++it) measured[it->idx()] = 1;
  }
  return measured;
}

// Each region of `result` a surface of its own (the remeshed path does not
// join them).
void OwnSurfaces(PipelineResult* result) {
  result->surfaces.clear();
  for (Region& r : result->regions) {
    r.surface_id = r.id;
    result->surfaces.push_back({.id = r.id,
                                .type = r.type,
                                .surface = r.surface,
                                .regions = {r.id},
                                .rms_distance = r.rms_distance,
                                .max_distance = r.max_distance});
  }
}

// Boundaries and features of `labels` (one per face of `mesh`) into `result`;
// result->mesh holds MeshStatistics(mesh), whose mean edge length is used.
absl::Status DescribeRegions(const Mesh& mesh, std::span<const int> labels,
                             const std::vector<Region>& regions, const PipelineParams& params,
                             const RunContext& ctx, PipelineResult* result) {
  ctx.Progress("topology", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(result->topology,
                           ExtractTopology(mesh, labels, regions, result->mesh.mean_edge_length,
                                           params.topology, ctx));
  MESHSEG_ASSIGN_OR_RETURN(result->features,
                           RecognizeFeatures(result->topology, regions, params.features));
  ctx.Progress("topology", 1.0);
  return absl::OkStatus();
}

// Boundaries and features of `segmentation` (of `mesh`; result->mesh holds
// MeshStatistics(mesh)) into `result`, with its regions, surfaces and
// estimates; returns its labels per mesh face.
absl::StatusOr<std::vector<int>> TakeSegmentation(const Mesh& mesh, Segmentation segmentation,
                                                  const PipelineParams& params,
                                                  const RunContext& ctx, PipelineResult* result) {
  MESHSEG_RETURN_IF_ERROR(
      DescribeRegions(mesh, segmentation.face_labels, segmentation.regions, params, ctx, result));
  result->vertex_labels = std::move(segmentation.vertex_labels);
  result->regions = std::move(segmentation.regions);
  result->surfaces = std::move(segmentation.surfaces);
  result->estimates = segmentation.estimates;
  return std::move(segmentation.face_labels);
}

}  // namespace

absl::StatusOr<std::vector<int>> SegmentMesh(const Mesh& mesh, const PipelineParams& params,
                                             const RunContext& ctx, PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the caller has decided
  MESHSEG_ASSIGN_OR_RETURN(
      Segmentation segmentation,
      Segment(mesh, curvature, result->mesh.mean_edge_length, segment, ctx));
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

absl::StatusOr<std::vector<int>> SegmentExact(const Mesh& mesh, const Exactness& exactness,
                                              const PipelineParams& params, const RunContext& ctx,
                                              PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  SegmentParams segment = params.segment;
  segment.exact_tolerance = exactness.tolerance;
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, SegmentExactFacets(mesh, segment, ctx));
  segmentation.estimates.exact_share = exactness.share;
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

absl::StatusOr<std::vector<int>> SegmentRemeshed(const Mesh& surface, const Mesh& mesh,
                                                 double edge_length, bool on_facets,
                                                 const PipelineParams& params,
                                                 const RunContext& ctx, PipelineResult* result,
                                                 const BinaryVertices* binary) {
  RemeshStats remesh;
  MESHSEG_ASSIGN_OR_RETURN(const Mesh& fine,
                           IsotropicRemesh(surface, edge_length, params.remesh, ctx, &remesh));
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(fine, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the remesh's vertices lie on chords, under the surface
  segment.on_facets = on_facets;      // the remesh's vertices lie on the input's facets
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(fine, curvature, segment, ctx));
  const double tolerance = segmentation.estimates.distance_tolerance;
  std::vector<int> labels =
      TransferFaceLabels(fine.tri, segmentation.face_labels, mesh.tri);
  result->vertex_labels = VertexLabelsFromFaces(mesh.tri, labels);
  result->regions = std::move(segmentation.regions);
  CompactRegions(&labels, &result->vertex_labels, &result->regions);
  RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  if (on_facets && RelabelFacesOffTheirSurface(
          mesh.tri, result->regions, kExactCorner * MeanEdgeLength(mesh.tri), &labels) > 0) {
    result->vertex_labels = VertexLabelsFromFaces(mesh.tri, labels);
    CompactRegions(&labels, &result->vertex_labels, &result->regions);
    RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  }
  if (binary != nullptr) {
    RefitPlanesBySeparation(mesh.tri, labels, *binary, &result->regions);
  }
  OwnSurfaces(result);
  result->mesh = MeshStatistics(mesh);
  MESHSEG_RETURN_IF_ERROR(DescribeRegions(mesh, labels, result->regions, params, ctx, result));
  result->estimates = segmentation.estimates;
  result->estimates.path = SegmentationPath::kRemeshed;
  result->remesh_edge_length = edge_length;
  result->remesh_face_count = static_cast<int64_t>(fine.tri.n_faces());
  result->remesh_fine_edge_length = remesh.fine_edge_length;
  return labels;
}

absl::StatusOr<std::vector<int>> SegmentBinary(const Mesh& mesh, const BinaryVertices& binary,
                                               double h, const PipelineParams& params,
                                               const RunContext& ctx, PipelineResult* result) {
  result->binary_occupancy = true;
  // The relaxed surface has the input's faces and vertex ids.
  Mesh relaxed;
  relaxed.tri = mesh.tri;
  BinaryVertices free = binary;
  if (!params.binary_relax_keeps_features) std::fill(free.feature.begin(), free.feature.end(), 0);
  const std::vector<Eigen::Vector3d> moved = RelaxTerraces(mesh.tri, free);
  for (auto v : relaxed.tri.vertices()) {
    const Eigen::Vector3d& p = moved[v.idx()];
    relaxed.tri.set_point(v, TriMesh::Point(p.x(), p.y(), p.z()));
  }
  relaxed.tri.update_normals();
  relaxed.face_of_input = mesh.face_of_input;
  relaxed.name = mesh.name;
  if (params.binary_surface == PipelineParams::BinarySurface::kSimplify) {
    // QEM on the relaxed surface, not the terraced one: measured against the
    // terraces, keeping them costs nothing and the remesh then segments
    // them. The feature vertices (which the relaxation kept in place) stay.
    const SimplifyParams simplify{
        .target_faces = std::max<int64_t>(
            1000, static_cast<int64_t>(params.binary_face_share * mesh.tri.n_faces())),
        .max_error = params.binary_max_error_voxels * h,
        .measure_hausdorff = false};
    absl::StatusOr<Simplification> simple = Simplify(relaxed.tri, simplify, free.feature, {}, ctx);
    if (!simple.ok()) return simple.status();
    result->simplified_face_count = static_cast<int64_t>(simple->mesh.tri.n_faces());
    // To the full (terraced) surface, as the result reports it.
    result->simplified_hausdorff = Hausdorff(mesh.tri, simple->mesh.tri).Max();
    return SegmentRemeshed(simple->mesh, mesh, MeanEdgeLength(mesh.tri), /*on_facets=*/false,
                           params, ctx, result, &binary);
  }
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(relaxed, params.curvature, ctx));
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation,
                           Segment(relaxed, curvature, params.segment, ctx));
  std::vector<int> labels = std::move(segmentation.face_labels);
  result->vertex_labels = std::move(segmentation.vertex_labels);
  result->regions = std::move(segmentation.regions);
  result->estimates = segmentation.estimates;
  // The relaxation moves curved surfaces by their curvature (up to the
  // edges' slack): surfaces are fitted on the original, unbiased vertices.
  RetypeCoaxialSpheresOnInputVertices(mesh.tri, labels, &result->regions);
  RefitOnInputVertices(mesh.tri, labels, segmentation.estimates.distance_tolerance,
                                          &result->regions);
  // Planes: the separator of the binary samples, sharper than any fit to
  // the vertices between them (separating_planes.h).
  RefitPlanesBySeparation(mesh.tri, labels, binary, &result->regions);
  result->mesh = MeshStatistics(mesh);
  MESHSEG_RETURN_IF_ERROR(DescribeRegions(mesh, labels, result->regions, params, ctx, result));
  return labels;
}

absl::StatusOr<std::vector<int>> SegmentReconstruction(const Reconstruction& reconstruction,
                                                       const PointCloud& cloud,
                                                       const PipelineParams& params,
                                                       const RunContext& ctx,
                                                       PipelineResult* result) {
  const Mesh& mesh = reconstruction.mesh;
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;
  segment.measured = MeasuredMask(mesh.tri, reconstruction.is_filled);
  // The vertices were projected onto fits to the points: how far one lies
  // off its surface is their noise averaged, not the resolution (energy.h).
  segment.point_noise = reconstruction.stats.noise;
  MESHSEG_ASSIGN_OR_RETURN(
      Segmentation segmentation,
      Segment(mesh, curvature, result->mesh.mean_edge_length, segment, ctx));
  // Each region's points: those whose nearest face it holds.
  const std::vector<int> nearest = PointLabels(
      mesh.tri, segmentation.face_labels, cloud.points, reconstruction.is_outlier);
  std::vector<std::vector<Eigen::Vector3d>> all_points(segmentation.regions.size());
  for (std::size_t k = 0; k < nearest.size(); ++k) {
    if (nearest[k] >= 0) all_points[nearest[k]].push_back(cloud.points[k]);
  }
  const double tolerance = segmentation.estimates.distance_tolerance;
  RefitToPoints(all_points, tolerance, &segmentation.regions);
  // A region's own points are those within its band: the segmentation's
  // distance tolerance th_dis, widened to 3 sigma of the cloud's noise. The
  // others are a neighbour's (the rounded band of a crease, faces given to
  // the wrong side), which the least-squares fit above still follows; the
  // surface is fitted again without them.
  const double band = std::max(tolerance, 3.0 * reconstruction.stats.noise);
  std::vector<std::vector<Eigen::Vector3d>> points(segmentation.regions.size());
  std::vector<uint8_t> trusted(segmentation.regions.size(), 0);
  for (const Region& region : segmentation.regions) {
    points[region.id] = WithinBand(region.surface, all_points[region.id], band);
    trusted[region.id] = !points[region.id].empty();
  }
  RefitToPoints(points, tolerance, &segmentation.regions);
  // Types compared on all of a region's points, each type on its own band.
  RetypeToPoints(all_points, band, reconstruction.stats.noise, &segmentation.regions,
                 &segmentation.surfaces, &points);
  // A narrow band's region may hold its neighbours' points beyond both its
  // creases, which bend its type (a chamfer into a torus): its type decided
  // again with each point on the nearest of a simpler type's surface and
  // its neighbours' (retype_beside_neighbours.h).
  RetypeBesideNeighbours(
      points,
      RegionNeighbours(mesh.tri, segmentation.face_labels, segmentation.regions.size()),
      reconstruction.stats.noise, &segmentation.regions, &segmentation.surfaces);
  // A point keeps its face's region within its noise band (2 sigma of the
  // cloud's noise); regions without points of their own (on the patches
  // that close unscanned areas) take no point from a neighbour.
  result->point_labels = PointLabelsBySurface(
      mesh.tri, segmentation.face_labels, segmentation.regions,
      {.keep_distance = 2.0 * reconstruction.stats.noise, .trusted = trusted}, cloud.points,
      reconstruction.is_outlier);
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

}  // namespace meshseg::pipeline_internal
