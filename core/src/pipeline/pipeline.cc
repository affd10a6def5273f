// RunPipeline(): read the input (reconstructing a point cloud into a mesh),
// then curvature -> segment -> topology -> features, and map the labels back
// to the faces or points of the input file.
#include "meshseg/pipeline.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"
#include "pipeline/input_labels.h"
#include "pipeline/point_labels.h"

namespace meshseg {
namespace {

absl::Status ValidateParams(const PipelineParams& params) {
  if (params.max_elements <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("pipeline: max_elements must be positive, got ", params.max_elements));
  }
  return absl::OkStatus();
}

bool IsPointCloudFormat(FileFormat format) {
  return format == FileFormat::kXyz || format == FileFormat::kPwn;
}

// Segments `mesh` and fills everything of `result` but the labels; returns
// the labels per mesh face.
absl::StatusOr<std::vector<int>> SegmentMesh(const Mesh& mesh, const PipelineParams& params,
                                             const RunContext& ctx, PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation,
                           Segment(mesh, curvature, params.segment, ctx));
  ctx.Progress("topology", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(result->topology,
                           ExtractTopology(mesh, segmentation.face_labels, segmentation.regions,
                                           params.topology, ctx));
  MESHSEG_ASSIGN_OR_RETURN(result->features,
                           RecognizeFeatures(result->topology, segmentation.regions,
                                             params.features));
  ctx.Progress("topology", 1.0);
  result->vertex_labels = std::move(segmentation.vertex_labels);
  result->regions = std::move(segmentation.regions);
  result->estimates = segmentation.estimates;
  return std::move(segmentation.face_labels);
}

absl::StatusOr<PipelineResult> RunOnPointCloud(const std::string& input_path,
                                               const PipelineParams& params,
                                               const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      PointCloud cloud,
      ReadPointCloud(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  MESHSEG_ASSIGN_OR_RETURN(Reconstruction reconstruction,
                           Reconstruct(cloud, params.reconstruct, ctx));
  PipelineResult result;
  result.from_point_cloud = true;
  result.point_count = static_cast<int64_t>(cloud.points.size());
  MESHSEG_ASSIGN_OR_RETURN(result.face_labels,
                           SegmentMesh(reconstruction.mesh, params, ctx, &result));
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
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> mesh_labels,
                           SegmentMesh(mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, mesh_labels);
  return result;
}

}  // namespace

absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  ctx.Progress("read", 0.0);
  bool point_cloud = params.format && IsPointCloudFormat(*params.format);
  if (!params.format || *params.format == FileFormat::kPly) {
    MESHSEG_ASSIGN_OR_RETURN(point_cloud, IsPointCloudFile(input_path));
  }
  absl::StatusOr<PipelineResult> result = point_cloud ? RunOnPointCloud(input_path, params, ctx)
                                                      : RunOnMesh(input_path, params, ctx);
  if (result.ok()) MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
  return result;
}

}  // namespace meshseg
