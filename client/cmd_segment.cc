// meshseg segment INPUT -o RESULT.json [--colored-ply OUT.ply] [--report REPORT.html]
//   [--step OUT.step [--unit U]] [--include-mesh] [--length-unit U]
//   [--distance-tolerance X] [--angle-tolerance DEG] [--format FMT]
//   [--server HOST:PORT [--request-id ID]] [--path exact|scan] [--exact-tolerance X]
//   [--freeform-fit on|off] [--freeform-fraction F]
//   [volume flags: client/volume_args.h]
// In-process by default; with --server the same result comes from the service.
#include <cstdio>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/memory_reuse.h"
#include "client/progress.h"
#include "client/report.h"
#include "client/volume_args.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/point_cloud.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

// The STEP file asked for with --step (and its --unit), or none.
struct StepRequest {
  std::string path;
  std::string unit;
};

absl::StatusOr<v1::SegmentationResult> SegmentOffline(const std::string& path,
                                                      const UploadOptions& options,
                                                      const StepRequest& step,
                                                      ProgressPrinter& progress) {
  MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(options.segment));
  MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(options.format_hint));
  MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(options.raw, &params));
  params.step_path = step.path;
  MESHSEG_ASSIGN_OR_RETURN(params.brep.length_unit,
                           StepUnitFromWire(step.unit, options.length_unit));
  params.include_mesh = options.include_mesh;
  params.length_unit = options.length_unit;
  RunContext ctx;
  ctx.on_progress = [&](std::string_view stage, double f) { progress.Update(stage, f); };
  MESHSEG_ASSIGN_OR_RETURN(const PipelineResult result, RunPipeline(path, params, ctx));
  progress.Finish();
  return ToProto(result);
}

// The server's result; with a StepRequest the server writes the STEP file
// too and it is fetched to `step.path` (when one was written).
absl::StatusOr<v1::SegmentationResult> SegmentOnServer(const Args& args, const std::string& path,
                                                       UploadOptions options,
                                                       const StepRequest& step,
                                                       ProgressPrinter& progress) {
  MESHSEG_ASSIGN_OR_RETURN(MeshsegClient client, ConnectFromArgs(args));
  options.step = !step.path.empty();
  options.step_unit = step.unit;
  v1::Job job;
  absl::StatusOr<v1::SegmentationResult> result =
      client.Segment(path, options, [&](const v1::JobEvent& e) { progress.Event(e); }, &job);
  progress.Finish();
  if (result.ok() && options.step && job.step_size() > 0) {
    MESHSEG_RETURN_IF_ERROR(client.SaveStep(job.job_id(), step.path));
  }
  return result;
}

// Writes the input coloured by region: a mesh with one colour per input face;
// a point cloud (whose result has point labels) as its points, one colour per
// point, as the reconstructed mesh is not part of the result.
absl::Status WriteColored(const std::string& input, const std::optional<FileFormat>& format,
                          const UploadOptions& options, const v1::SegmentationResult& result,
                          const std::string& out) {
  if (result.has_volume()) {  // the surface extracted from the volume
    MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(options.segment));
    MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(options.raw, &params));
    params.volume.read.format = format;
    const absl::StatusOr<VolumeSurface> surface = ExtractSurface(input, params.volume);
    if (!surface.ok()) return surface.status();
    if (surface->mesh.face_of_input.size() != static_cast<std::size_t>(result.face_labels_size())) {
      return absl::InternalError("colored ply: the volume's surface differs from the result's");
    }
    std::vector<int> labels(surface->mesh.tri.n_faces(), -1);
    for (std::size_t i = 0; i < surface->mesh.face_of_input.size(); ++i) {
      const int f = surface->mesh.face_of_input[i];
      if (f >= 0) labels[f] = result.face_labels(static_cast<int>(i));
    }
    return WriteColoredPly(surface->mesh.tri, labels, out);
  }
  if (result.point_labels_size() > 0) {
    MESHSEG_ASSIGN_OR_RETURN(const PointCloud cloud, ReadPointCloud(input, {.format = format}));
    const std::vector<int> labels(result.point_labels().begin(), result.point_labels().end());
    if (labels.size() != cloud.points.size()) {
      return absl::InternalError(absl::StrCat("colored ply: result has ", labels.size(),
                                              " point labels, input has ", cloud.points.size(),
                                              " points"));
    }
    return WriteColoredPointPly(cloud, labels, out);
  }
  MESHSEG_ASSIGN_OR_RETURN(const Mesh& mesh, ReadMesh(input, {.format = format}));
  if (mesh.face_of_input.size() != static_cast<std::size_t>(result.face_labels_size())) {
    return absl::InternalError(absl::StrCat("colored ply: result has ", result.face_labels_size(),
                                            " face labels, input has ",
                                            mesh.face_of_input.size(), " faces"));
  }
  std::vector<int> labels(mesh.tri.n_faces(), -1);
  for (std::size_t i = 0; i < mesh.face_of_input.size(); ++i) {
    if (mesh.face_of_input[i] >= 0) labels[mesh.face_of_input[i]] = result.face_labels(i);
  }
  return WriteColoredPly(mesh.tri, labels, out);
}

}  // namespace

absl::Status RunSegment(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv,
                  {"-o", "--colored-ply", "--distance-tolerance", "--angle-tolerance", "--format",
                   "--server", "--report", "--step", "--unit", "--length-unit", "--request-id",
                   "--path", "--exact-tolerance", "--iso", "--volume-mode", "--dims", "--spacing",
                   "--origin", "--type", "--freeform-fit", "--freeform-fraction"},
                  {"--include-mesh", kBigEndianSwitch, "--open"}, 1));
  const std::string& input = args.positional(0);
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o RESULT.json is required");

  UploadOptions options;
  options.format_hint = args.Value("--format").value_or("");
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> dist, args.Double("--distance-tolerance"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> angle, args.Double("--angle-tolerance"));
  if (dist) options.segment.set_distance_tolerance(*dist);
  if (angle) options.segment.set_angle_tolerance_deg(*angle);
  MESHSEG_RETURN_IF_ERROR(VolumeOptionsFromArgs(args, &options));
  if (const std::optional<std::string> path = args.Value("--path")) {
    if (*path == "exact") {
      options.segment.set_segmentation_path(v1::SEGMENTATION_PATH_EXACT_FACETS);
    } else if (*path == "scan") {
      options.segment.set_segmentation_path(v1::SEGMENTATION_PATH_SCAN);
    } else {
      return absl::InvalidArgumentError(
          absl::StrCat("--path must be exact or scan, got \"", *path, "\""));
    }
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> exact_tol, args.Double("--exact-tolerance"));
  if (exact_tol) options.segment.set_exact_tolerance(*exact_tol);
  options.segment.set_open_unsupported(args.Has("--open"));
  if (const std::optional<std::string> fit = args.Value("--freeform-fit")) {
    if (*fit != "on" && *fit != "off") {
      return absl::InvalidArgumentError(
          absl::StrCat("--freeform-fit must be on or off, got \"", fit->substr(0, 64), "\""));
    }
    options.segment.set_freeform_fit(*fit == "on");
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> fraction,
                           args.Double("--freeform-fraction"));
  if (fraction) options.segment.set_freeform_face_fraction(*fraction);
  // Same validation on both paths (the server repeats it).
  MESHSEG_RETURN_IF_ERROR(FromProto(options.segment).status());
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<FileFormat> format,
                           FormatFromHint(options.format_hint));

  options.include_mesh = args.Has("--include-mesh");
  options.length_unit = args.Value("--length-unit").value_or("");
  options.request_id = args.Value("--request-id").value_or("");
  // --unit empty: the STEP file takes --length-unit, else millimetres.
  const StepRequest step{args.Value("--step").value_or(""), args.Value("--unit").value_or("")};
  if (step.path.empty() && args.Has("--unit")) {
    return absl::InvalidArgumentError("--unit needs --step OUT.step");
  }
  if (args.Has("--request-id") && !args.Has("--server")) {
    return absl::InvalidArgumentError(
        "--request-id needs --server HOST:PORT (it makes a server upload idempotent)");
  }
  // Checked here as the server checks them, before any work.
  MESHSEG_RETURN_IF_ERROR(StepUnitFromWire(step.unit, options.length_unit).status());
  // In process, the pipeline's freed arrays are reused by its next stages.
  if (!args.Has("--server")) KeepFreedMemoryForReuse();
  ProgressPrinter progress;
  absl::StatusOr<v1::SegmentationResult> result =
      args.Has("--server") ? SegmentOnServer(args, input, options, step, progress)
                           : SegmentOffline(input, options, step, progress);
  if (!result.ok()) return result.status();
  MESHSEG_ASSIGN_OR_RETURN(const std::string json, ResultJson(*result));
  MESHSEG_RETURN_IF_ERROR(WriteTextFile(*out, json));
  if (const std::optional<std::string> ply = args.Value("--colored-ply")) {
    MESHSEG_RETURN_IF_ERROR(WriteColored(input, format, options, *result, *ply));
  }
  if (const std::optional<std::string> report = args.Value("--report")) {
    MESHSEG_RETURN_IF_ERROR(WriteHtmlReport(*report,
                                            std::filesystem::path(input).filename().string(),
                                            *result, input, format, progress.Timings()));
    std::printf("wrote %s\n", report->c_str());
  }
  std::fputs(RegionTable(*result).c_str(), stdout);
  std::fputs(TopologySummary(*result).c_str(), stdout);
  std::printf("wrote %s\n", out->c_str());
  if (!step.path.empty()) {
    std::fputs(BrepSummary(result->brep()).c_str(), stdout);
    if (!result->brep().error().empty()) {
      return absl::FailedPreconditionError(
          absl::StrCat("no STEP file written: ", result->brep().error()));
    }
    std::printf("wrote %s\n", step.path.c_str());
  }
  return absl::OkStatus();
}

}  // namespace meshseg::cli
