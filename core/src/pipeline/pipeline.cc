#include "meshseg/pipeline.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "pipeline/input_labels.h"

namespace meshseg {
namespace {

absl::Status ValidateParams(const PipelineParams& params) {
  if (params.max_elements <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("pipeline: max_elements must be positive, got ", params.max_elements));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  ctx.Progress("read", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(
      Mesh mesh,
      ReadMesh(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));

  PipelineResult result;
  result.mesh = MeshStatistics(mesh);
  // Segmentation is wired in once the curvature and segment stages land;
  // until then every face is reported without a region.
  const std::vector<int> mesh_labels(mesh.tri.n_faces(), -1);
  result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, mesh_labels);
  result.vertex_labels.assign(mesh.tri.n_vertices(), -1);
  return result;
}

}  // namespace meshseg
