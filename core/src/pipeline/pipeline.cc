// RunPipeline(): read the input (reconstructing a point cloud into a mesh),
// then curvature -> segment -> topology -> features, and map the labels back
// to the faces or points of the input file.
#include "meshseg/pipeline.h"

#include <filesystem>
#include <optional>
#include <span>
#include <utility>

#include <tbb/parallel_invoke.h>

#include "absl/strings/str_cat.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"
#include "pipeline/finite_result.h"
#include "pipeline/freeform_regions.h"
#include "pipeline/input_labels.h"
#include "pipeline/memory_model.h"
#include "pipeline/mesh_geometry.h"
#include "pipeline/segment_input.h"

namespace meshseg {
namespace {

using pipeline_internal::SegmentMesh;
using pipeline_internal::SegmentExact;
using pipeline_internal::SegmentRemeshed;
using pipeline_internal::SegmentBinary;
using pipeline_internal::SegmentReconstruction;

absl::Status ValidateParams(const PipelineParams& params) {
  if (params.max_elements <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("pipeline: max_elements must be positive, got ", params.max_elements));
  }
  if (params.memory_budget_bytes < 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "pipeline: memory_budget_bytes must be >= 0, got ", params.memory_budget_bytes));
  }
  if (params.length_unit.empty()) return absl::OkStatus();
  const std::string unit = CanonicalLengthUnit(params.length_unit);
  if (unit.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("pipeline: length_unit \"",
                                                   params.length_unit.substr(0, 64),
                                                   "\" is not one of ", LengthUnitList()));
  }
  // The STEP file declares its unit over unscaled coordinates: any other
  // unit than the input's would scale the part.
  if (!params.step_path.empty() && CanonicalLengthUnit(params.brep.length_unit) != unit) {
    return absl::InvalidArgumentError(absl::StrCat(
        "pipeline: the STEP file's length unit \"", params.brep.length_unit.substr(0, 64),
        "\" is not the input's length_unit \"", unit, "\" (coordinates are written unscaled)"));
  }
  return absl::OkStatus();
}

// Copies the mesh the result's ids refer to into `result` when params ask
// for it; `face_of_input` as Mesh::face_of_input (empty: a reconstruction).
void AttachMesh(const Mesh& mesh, std::span<const int> face_of_input, const PipelineParams& params,
                PipelineResult* result) {
  if (params.include_mesh) {
    result->mesh_geometry = pipeline_internal::GeometryOf(mesh.tri, face_of_input);
  }
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

bool IsPointCloudFormat(FileFormat format) {
  return format == FileFormat::kXyz || format == FileFormat::kPwn;
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

absl::StatusOr<PipelineResult> RunOnVolume(const std::string& input_path,
                                           const PipelineParams& params, const RunContext& ctx) {
  VolumeParams volume = params.volume;
  if (params.format) volume.read.format = params.format;
  const absl::StatusOr<VolumeSurface> surface = ExtractSurface(input_path, volume, ctx);
  if (!surface.ok()) return surface.status();
  PipelineResult result;
  result.from_volume = true;
  result.volume = surface->info;
  result.iso_value = surface->iso;
  const double h = surface->info.geometry.Spacing().minCoeff();
  MESHSEG_ASSIGN_OR_RETURN(
      const std::vector<int> labels,
      surface->binary
          ? SegmentBinary(surface->mesh,
                          {surface->feature_vertex, surface->edge_inside, surface->edge_outside}, h,
                          params, ctx, &result)
                      : SegmentMesh(surface->mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(surface->mesh.face_of_input, labels);
  MESHSEG_RETURN_IF_ERROR(ExportStep(surface->mesh, labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(
      pipeline_internal::FitFreeform(surface->mesh, labels, params, ctx, &result));
  AttachMesh(surface->mesh, {}, params, &result);  // the extracted surface; no input faces
  return result;
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
                           SegmentReconstruction(reconstruction, cloud, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(
      ExportStep(reconstruction.mesh, result.face_labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(reconstruction.mesh, result.face_labels,
                                                         params, ctx, &result));
  result.point_outlier_count = reconstruction.stats.outlier_count;
  result.face_filled = reconstruction.is_filled;
  result.filled_face_count = reconstruction.stats.filled_face_count;
  result.filled_area = reconstruction.stats.filled_area;
  AttachMesh(reconstruction.mesh, {}, params, &result);
  return result;
}

absl::StatusOr<PipelineResult> RunOnMesh(const std::string& input_path,
                                         const PipelineParams& params, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Mesh& mesh,
      ReadMesh(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  PipelineResult result;
  // The three tests of what kind of mesh this is only read it, so they run
  // side by side; on a binary or exact input the later ones are wasted work
  // on an otherwise idle core, never a different answer.
  const bool estimate_exactness =
      params.segment.exact != ExactMode::kNever && params.remesh.mode != RemeshMode::kAlways;
  std::optional<BinaryLattice> lattice;
  Exactness exactness;
  TessellationShape shape;
  tbb::parallel_invoke(
      [&] { lattice = DetectBinaryLattice(mesh.tri); },
      [&] {
        if (estimate_exactness) exactness = EstimateExactness(mesh, params.segment.exact_tolerance);
      },
      [&] { shape = Assess(mesh, params.remesh); });
  // Binary occupancy first: a terraced surface's facets lie exactly in the
  // planes of their neighbours, so it would pass for an exact tessellation.
  if (lattice) {
    MESHSEG_ASSIGN_OR_RETURN(const BinaryVertices binary,
                             BinaryMeshFeatures(mesh.tri, *lattice, params.volume));
    MESHSEG_ASSIGN_OR_RETURN(
        const std::vector<int> labels,
        SegmentBinary(mesh, binary, lattice->spacing.minCoeff(), params, ctx, &result));
    result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, labels);
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, labels, params, ctx, &result));
    AttachMesh(mesh, mesh.face_of_input, params, &result);
    return result;
  }
  // An exact tessellation is segmented facet by facet, as read; the share
  // of exact facets is reported either way (estimates.exact_share).
  if (estimate_exactness &&
      (exactness.exact || params.segment.exact == ExactMode::kAlways)) {
    MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> labels,
                             SegmentExact(mesh, exactness, params, ctx, &result));
    result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, labels);
    MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, labels, params, ctx, &result));
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, labels, params, ctx, &result));
    AttachMesh(mesh, mesh.face_of_input, params, &result);
    return result;
  }
  const bool remesh = params.remesh.mode == RemeshMode::kAlways ||
                      (params.remesh.mode == RemeshMode::kAuto && shape.cad_like);
  const double edge_length = params.remesh.target_edge_length > 0.0
                                 ? params.remesh.target_edge_length
                                 : shape.target_edge_length;
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> mesh_labels,
                           remesh ? SegmentRemeshed(mesh, mesh, edge_length, true, params, ctx, &result)
                                  : SegmentMesh(mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, mesh_labels);
  result.estimates.exact_tolerance = exactness.tolerance;
  result.estimates.exact_share = exactness.share;
  MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, mesh_labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, mesh_labels, params, ctx, &result));
  AttachMesh(mesh, mesh.face_of_input, params, &result);
  return result;
}

}  // namespace

absl::StatusOr<MemoryEstimate> EstimateJobMemory(const std::string& input_path,
                                                 const PipelineParams& params) {
  MemoryEstimate estimate;
  std::optional<FileFormat> format = params.format;
  if (!format) {
    const absl::StatusOr<FileFormat> detected = DetectFileFormat(input_path);
    if (detected.ok() && IsVolumeFormat(*detected)) format = *detected;
  }
  if (format && IsVolumeFormat(*format)) {  // costed from the volume's header
    VolumeReadOptions read = params.volume.read;
    read.format = format;
    MESHSEG_ASSIGN_OR_RETURN(const VolumeInfo info, ReadVolumeInfo(input_path, read));
    std::error_code ec;
    const auto file_bytes = std::filesystem::file_size(input_path, ec);
    int64_t extra = 0;
    estimate.input = pipeline_internal::VolumeInputSize(
        info, params, ec ? 0 : static_cast<int64_t>(file_bytes), &extra);
    PipelineParams no_remesh = params;  // a volume's surface is not remeshed
    no_remesh.remesh.mode = RemeshMode::kNever;
    estimate.peak_bytes =
        pipeline_internal::PeakBytes(estimate.input, no_remesh) +
        static_cast<int64_t>(pipeline_internal::kSafetyMargin * static_cast<double>(extra));
    return estimate;
  }
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
  std::optional<FileFormat> format = params.format;
  if (!format) {
    const absl::StatusOr<FileFormat> detected = DetectFileFormat(input_path);
    if (detected.ok() && IsVolumeFormat(*detected)) format = *detected;
  }
  if (format && IsVolumeFormat(*format)) {
    absl::StatusOr<PipelineResult> result = RunOnVolume(input_path, params, ctx);
    if (result.ok()) MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
    return result;
  }
  bool point_cloud = params.format && IsPointCloudFormat(*params.format);
  if (!params.format || *params.format == FileFormat::kPly) {
    MESHSEG_ASSIGN_OR_RETURN(point_cloud, IsPointCloudFile(input_path));
  }
  absl::StatusOr<PipelineResult> result = point_cloud ? RunOnPointCloud(input_path, params, ctx)
                                                      : RunOnMesh(input_path, params, ctx);
  if (result.ok()) {
    result->length_unit = CanonicalLengthUnit(params.length_unit);
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::CheckResultFinite(
        std::filesystem::path(input_path).filename().string(), *result));
  }
  return result;
}

}  // namespace meshseg
