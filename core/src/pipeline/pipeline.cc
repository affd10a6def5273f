// RunPipeline(): read the input (reconstructing a point cloud into a mesh),
// then curvature -> segment -> topology -> features, and map the labels back
// to the faces or points of the input file.
#include "meshseg/pipeline.h"

#include <filesystem>
#include <span>
#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"
#include "pipeline/finite_result.h"
#include "pipeline/input_labels.h"
#include "pipeline/memory_model.h"
#include "pipeline/point_labels.h"
#include "pipeline/refit_regions.h"
#include "pipeline/remeshed_labels.h"

namespace meshseg {
namespace {

// A CAD export's vertices lie on their surfaces to rounding: a face whose
// corners miss its region's refitted surface by more than this, in l_avg of
// the input, may belong next door.
constexpr double kExactCorner = 1e-4;

absl::Status ValidateParams(const PipelineParams& params) {
  if (params.max_elements <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("pipeline: max_elements must be positive, got ", params.max_elements));
  }
  if (params.memory_budget_bytes < 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "pipeline: memory_budget_bytes must be >= 0, got ", params.memory_budget_bytes));
  }
  return absl::OkStatus();
}

// Returns OK if the job's estimated peak fits params.memory_budget_bytes.
absl::Status CheckMemoryBudget(const std::string& input_path, const PipelineParams& params) {
  if (params.memory_budget_bytes == 0) return absl::OkStatus();
  MESHSEG_ASSIGN_OR_RETURN(const MemoryEstimate estimate, EstimateJobMemory(input_path, params));
  if (estimate.peak_bytes <= params.memory_budget_bytes) return absl::OkStatus();
  const InputSize& in = estimate.input;
  return absl::ResourceExhaustedError(absl::StrCat(
      "pipeline: \"", std::filesystem::path(input_path).filename().string(), "\": ",
      in.point_cloud ? absl::StrCat(in.vertex_count, " points")
                     : absl::StrCat(in.face_count, " faces, ", in.vertex_count, " vertices"),
      " declared need an estimated ", estimate.peak_bytes, " bytes, over the memory budget of ",
      params.memory_budget_bytes));
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

bool IsPointCloudFormat(FileFormat format) {
  return format == FileFormat::kXyz || format == FileFormat::kPwn;
}

// Boundaries and features of `labels` (one per face of `mesh`) into `result`.
absl::Status DescribeRegions(const Mesh& mesh, std::span<const int> labels,
                             const std::vector<Region>& regions, const PipelineParams& params,
                             const RunContext& ctx, PipelineResult* result) {
  ctx.Progress("topology", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(result->topology,
                           ExtractTopology(mesh, labels, regions, params.topology, ctx));
  MESHSEG_ASSIGN_OR_RETURN(result->features,
                           RecognizeFeatures(result->topology, regions, params.features));
  ctx.Progress("topology", 1.0);
  return absl::OkStatus();
}

// Boundaries and features of `segmentation` (of `mesh`) into `result`, with
// its regions, surfaces and estimates; returns its labels per mesh face.
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

// Segments `mesh` and fills everything of `result` but the labels; returns
// the labels per mesh face.
absl::StatusOr<std::vector<int>> SegmentMesh(const Mesh& mesh, const PipelineParams& params,
                                             const RunContext& ctx, PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the caller has decided
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(mesh, curvature, segment, ctx));
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

// An exact tessellation (meshseg/segment.h: SegmentExactFacets), facet by
// facet on the input itself: no curvature, no remesh.
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

// A CAD tessellation (meshseg/remesh.h): segments an isotropic remesh, then
// labels the faces and vertices of `mesh` from it and extracts boundaries and
// features on `mesh` itself, so curve vertex ids are ids of the input.
absl::StatusOr<std::vector<int>> SegmentRemeshed(const Mesh& mesh, double edge_length,
                                                 const PipelineParams& params,
                                                 const RunContext& ctx, PipelineResult* result) {
  RemeshStats remesh;
  MESHSEG_ASSIGN_OR_RETURN(const Mesh fine,
                           IsotropicRemesh(mesh, edge_length, params.remesh, ctx, &remesh));
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(fine, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the remesh's vertices lie on chords, under the surface
  segment.on_facets = true;  // the remesh's vertices lie on the input's facets
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(fine, curvature, segment, ctx));
  const double tolerance = segmentation.estimates.distance_tolerance;
  std::vector<int> labels =
      pipeline_internal::TransferFaceLabels(fine.tri, segmentation.face_labels, mesh.tri);
  result->vertex_labels = pipeline_internal::VertexLabelsFromFaces(mesh.tri, labels);
  result->regions = std::move(segmentation.regions);
  pipeline_internal::CompactRegions(&labels, &result->vertex_labels, &result->regions);
  pipeline_internal::RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  if (pipeline_internal::RelabelFacesOffTheirSurface(
          mesh.tri, result->regions, kExactCorner * MeanEdgeLength(mesh.tri), &labels) > 0) {
    result->vertex_labels = pipeline_internal::VertexLabelsFromFaces(mesh.tri, labels);
    pipeline_internal::CompactRegions(&labels, &result->vertex_labels, &result->regions);
    pipeline_internal::RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  }
  OwnSurfaces(result);
  MESHSEG_RETURN_IF_ERROR(DescribeRegions(mesh, labels, result->regions, params, ctx, result));
  result->mesh = MeshStatistics(mesh);
  result->estimates = segmentation.estimates;
  result->estimates.path = SegmentationPath::kRemeshed;
  result->remesh_edge_length = edge_length;
  result->remesh_face_count = static_cast<int64_t>(fine.tri.n_faces());
  result->remesh_fine_edge_length = remesh.fine_edge_length;
  return labels;
}

// Writes the STEP file when params ask for one (`labels` one per face of
// `mesh`, the mesh the topology refers to).
absl::Status ExportStep(const Mesh& mesh, std::span<const int> labels,
                        const PipelineParams& params, const RunContext& ctx,
                        PipelineResult* result) {
  if (params.step_path.empty()) return absl::OkStatus();
  BrepParams brep = params.brep;
  if (!brep.noise_sigma) brep.noise_sigma = result->estimates.noise_sigma;
  absl::StatusOr<BrepReport> report =
      WriteStep(mesh, labels, result->regions, result->topology, params.step_path, brep, ctx);
  if (absl::IsCancelled(report.status())) return report.status();
  if (report.ok()) {
    result->brep = *std::move(report);
  } else {
    result->brep_error = std::string(report.status().message());
  }
  return absl::OkStatus();
}

absl::StatusOr<PipelineResult> RunOnPointCloud(const std::string& input_path,
                                               const PipelineParams& params,
                                               const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      PointCloud cloud,
      ReadPointCloud(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::CheckCoordinateRange(cloud.name, cloud.points));
  MESHSEG_ASSIGN_OR_RETURN(Reconstruction reconstruction,
                           Reconstruct(cloud, params.reconstruct, ctx));
  PipelineResult result;
  result.from_point_cloud = true;
  result.point_count = static_cast<int64_t>(cloud.points.size());
  MESHSEG_ASSIGN_OR_RETURN(result.face_labels,
                           SegmentMesh(reconstruction.mesh, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(
      ExportStep(reconstruction.mesh, result.face_labels, params, ctx, &result));
  result.point_labels = pipeline_internal::PointLabels(
      reconstruction.mesh.tri, result.face_labels, cloud.points, reconstruction.is_outlier);
  return result;
}

absl::StatusOr<PipelineResult> RunOnMesh(const std::string& input_path,
                                         const PipelineParams& params, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      Mesh mesh,
      ReadMesh(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  PipelineResult result;
  // An exact tessellation is segmented facet by facet, as read; the share
  // of exact facets is reported either way (estimates.exact_share).
  Exactness exactness;
  if (params.segment.exact != ExactMode::kNever && params.remesh.mode != RemeshMode::kAlways) {
    exactness = EstimateExactness(mesh, params.segment.exact_tolerance);
    if (exactness.exact || params.segment.exact == ExactMode::kAlways) {
      MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> labels,
                               SegmentExact(mesh, exactness, params, ctx, &result));
      result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, labels);
      MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, labels, params, ctx, &result));
      return result;
    }
  }
  const TessellationShape shape = Assess(mesh, params.remesh);
  const bool remesh = params.remesh.mode == RemeshMode::kAlways ||
                      (params.remesh.mode == RemeshMode::kAuto && shape.cad_like);
  const double edge_length = params.remesh.target_edge_length > 0.0
                                 ? params.remesh.target_edge_length
                                 : shape.target_edge_length;
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> mesh_labels,
                           remesh ? SegmentRemeshed(mesh, edge_length, params, ctx, &result)
                                  : SegmentMesh(mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, mesh_labels);
  result.estimates.exact_tolerance = exactness.tolerance;
  result.estimates.exact_share = exactness.share;
  MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, mesh_labels, params, ctx, &result));
  return result;
}

}  // namespace

absl::StatusOr<MemoryEstimate> EstimateJobMemory(const std::string& input_path,
                                                 const PipelineParams& params) {
  MemoryEstimate estimate;
  MESHSEG_ASSIGN_OR_RETURN(estimate.input, ProbeInput(input_path, params.format));
  estimate.peak_bytes = pipeline_internal::PeakBytes(estimate.input, params);
  return estimate;
}

absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(CheckMemoryBudget(input_path, params));
  ctx.Progress("read", 0.0);
  bool point_cloud = params.format && IsPointCloudFormat(*params.format);
  if (!params.format || *params.format == FileFormat::kPly) {
    MESHSEG_ASSIGN_OR_RETURN(point_cloud, IsPointCloudFile(input_path));
  }
  absl::StatusOr<PipelineResult> result = point_cloud ? RunOnPointCloud(input_path, params, ctx)
                                                      : RunOnMesh(input_path, params, ctx);
  if (result.ok()) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::CheckResultFinite(
        std::filesystem::path(input_path).filename().string(), *result));
  }
  return result;
}

}  // namespace meshseg
