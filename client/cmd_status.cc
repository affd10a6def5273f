// meshseg status JOB [--server HOST:PORT]: the job's state in one line.
#include <cstdio>

#include "client/commands.h"
#include "client/report.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunStatus(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"--server"}, {}, 1));
  MESHSEG_ASSIGN_OR_RETURN(MeshsegClient client, ConnectFromArgs(args));
  MESHSEG_ASSIGN_OR_RETURN(const v1::Job job, client.GetJob(args.positional(0)));
  std::printf("%s\n", JobLine(job).c_str());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
