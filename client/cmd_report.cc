// meshseg report RESULT.json [MESH] -o REPORT.html [--format FMT]
// The HTML report of a saved result; MESH (the file that was segmented) adds
// the 3D view.
#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/html_report.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {
namespace {

absl::StatusOr<v1::SegmentationResult> ReadResultJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("cannot read \"", path, "\""));
  std::stringstream text;
  text << in.rdbuf();
  v1::SegmentationResult result;
  google::protobuf::util::JsonParseOptions options;
  // A result written by a newer meshseg may carry fields this one lacks.
  options.ignore_unknown_fields = true;
  const auto status = google::protobuf::util::JsonStringToMessage(text.str(), &result, options);
  if (!status.ok()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "\"", path, "\" is not a result JSON: ", std::string(status.message()).substr(0, 200)));
  }
  return result;
}

}  // namespace

absl::Status WriteHtmlReport(const std::string& out, const std::string& title,
                             const v1::SegmentationResult& result,
                             const std::optional<std::string>& mesh_path,
                             const std::optional<FileFormat>& format,
                             std::vector<StageTime> timings) {
  ReportInputs inputs;
  inputs.title = title;
  inputs.result = &result;
  inputs.timings = std::move(timings);
  if (mesh_path) {
    MESHSEG_ASSIGN_OR_RETURN(inputs.geometry, GeometryForReport(*mesh_path, result, format));
  } else {
    inputs.geometry.note =
        "no mesh given: `meshseg report RESULT.json MESH -o report.html` adds the 3D view";
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::string html, HtmlReport(inputs));
  return WriteTextFile(out, html);
}

absl::Status RunReport(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"-o", "--format"}, {}, 1, 2));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o REPORT.html is required");
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<FileFormat> format,
                           FormatFromHint(args.Value("--format").value_or("")));
  MESHSEG_ASSIGN_OR_RETURN(const v1::SegmentationResult result, ReadResultJson(args.positional(0)));
  std::optional<std::string> mesh;
  if (args.positional_count() == 2) mesh = args.positional(1);
  const std::string title =
      std::filesystem::path(mesh.value_or(args.positional(0))).filename().string();
  MESHSEG_RETURN_IF_ERROR(WriteHtmlReport(*out, title, result, mesh, format, {}));
  std::printf("wrote %s\n", out->c_str());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
