// meshseg brep RESULT.json MESH -o OUT.step [--unit U]: the B-rep of a saved
// result as STEP, built on the mesh the result was computed on.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/report.h"
#include "meshseg/brep.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {
namespace {

absl::StatusOr<std::string> ReadTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot open \"", path, "\""));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return absl::InternalError(absl::StrCat("cannot read \"", path, "\""));
  return text.str();
}

}  // namespace

absl::Status RunBrep(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"-o", "--unit"}, {}, 2));
  const std::string& result_path = args.positional(0);
  const std::string& mesh_path = args.positional(1);
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o OUT.step is required");

  MESHSEG_ASSIGN_OR_RETURN(const std::string json, ReadTextFile(result_path));
  absl::StatusOr<v1::SegmentationResult> message = ParseResultJson(json);
  if (!message.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("\"", result_path, "\": ", message.status().message()));
  }
  absl::StatusOr<PipelineResult> result = FromProto(*message);
  if (!result.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("\"", result_path, "\": ", result.status().message()));
  }
  if (result->from_point_cloud) {
    return absl::InvalidArgumentError(
        absl::StrCat("\"", result_path,
                     "\" is the result of a point cloud, whose mesh is not kept: use "
                     "meshseg segment CLOUD --step OUT.step"));
  }
  absl::StatusOr<Mesh> mesh = ReadMesh(mesh_path);
  if (!mesh.ok()) return mesh.status();
  if (mesh->face_of_input.size() != result->face_labels.size() ||
      static_cast<int64_t>(mesh->tri.n_vertices()) != message->mesh().vertex_count()) {
    return absl::InvalidArgumentError(
        absl::StrCat("\"", mesh_path, "\" has ", mesh->face_of_input.size(), " faces and ",
                     mesh->tri.n_vertices(), " vertices, \"", result_path, "\" was computed on ",
                     result->face_labels.size(), " and ", message->mesh().vertex_count()));
  }
  std::vector<int> labels(mesh->tri.n_faces(), -1);
  for (size_t i = 0; i < mesh->face_of_input.size(); ++i) {
    if (mesh->face_of_input[i] >= 0) labels[mesh->face_of_input[i]] = result->face_labels[i];
  }
  BrepParams params{.length_unit = args.Value("--unit").value_or(BrepParams{}.length_unit),
                    .noise_sigma = result->estimates.noise_sigma};
  MESHSEG_ASSIGN_OR_RETURN(const BrepReport report, WriteStep(*mesh, labels, result->regions,
                                                              result->topology, *out, params));
  result->brep = report;
  v1::SegmentationResult with_report = ToProto(*result);
  std::fputs(BrepSummary(with_report.brep()).c_str(), stdout);
  std::printf("wrote %s\n", out->c_str());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
