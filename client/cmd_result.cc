// meshseg result JOB -o RESULT.json [--server HOST:PORT]: the result JSON of
// a finished job (byte-identical to `meshseg segment` for the same input).
#include <cstdio>

#include "client/commands.h"
#include "client/report.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunResult(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"--server", "-o"}, {}, 1));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o RESULT.json is required");
  MESHSEG_ASSIGN_OR_RETURN(MeshsegClient client, ConnectFromArgs(args));
  MESHSEG_ASSIGN_OR_RETURN(const v1::SegmentationResult result,
                           client.Result(args.positional(0)));
  MESHSEG_ASSIGN_OR_RETURN(const std::string json, ResultJson(result));
  MESHSEG_RETURN_IF_ERROR(WriteTextFile(*out, json));
  std::fputs(RegionTable(result).c_str(), stdout);
  std::fputs(TopologySummary(result).c_str(), stdout);
  std::printf("wrote %s\n", out->c_str());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
