// File: commands.h
// -----------------------------------------------------------------------------
// The `meshseg` subcommands, one file each (cmd_<name>.cc). Each takes the
// arguments after its name and returns OK or the one error main prints.
#ifndef MESHSEG_CLIENT_COMMANDS_H_
#define MESHSEG_CLIENT_COMMANDS_H_

#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "client/args.h"
#include "client/job_progress.h"
#include "client/meshseg_client.h"
#include "meshseg/mesh.h"

namespace meshseg::cli {

using Argv = std::vector<std::string>;

absl::Status RunInfo(const Argv& argv);
absl::Status RunGenerate(const Argv& argv);
absl::Status RunConvert(const Argv& argv);
absl::Status RunReconstruct(const Argv& argv);
absl::Status RunSegment(const Argv& argv);
absl::Status RunJobs(const Argv& argv);
absl::Status RunStatus(const Argv& argv);
absl::Status RunWatch(const Argv& argv);
absl::Status RunResult(const Argv& argv);
absl::Status RunCancel(const Argv& argv);
absl::Status RunReport(const Argv& argv);
absl::Status RunBrep(const Argv& argv);
absl::Status RunSimplify(const Argv& argv);
absl::Status RunSubdivideFit(const Argv& argv);

// The server of a job command: --server, else $MESHSEG_SERVER.
// Errors (INVALID_ARGUMENT): neither is set.
absl::StatusOr<MeshsegClient> ConnectFromArgs(const Args& args);

// Writes `text` to `path`. Errors: INTERNAL naming the path.
absl::Status WriteTextFile(const std::string& path, const std::string& text);

// Writes the HTML report (html_report.h) of `result` to `out`, drawing the
// file at `mesh_path` (the segmented input) when given. Errors: those of
// GeometryForReport and WriteTextFile.
absl::Status WriteHtmlReport(const std::string& out, const std::string& title,
                             const v1::SegmentationResult& result,
                             const std::optional<std::string>& mesh_path,
                             const std::optional<FileFormat>& format,
                             std::vector<StageTime> timings);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_COMMANDS_H_
