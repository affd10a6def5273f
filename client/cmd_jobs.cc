// meshseg jobs [--server HOST:PORT]: one line per job the server knows.
#include <cstdio>

#include "client/commands.h"
#include "client/report.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunJobs(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"--server"}, {}, 0));
  MESHSEG_ASSIGN_OR_RETURN(MeshsegClient client, ConnectFromArgs(args));
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<v1::Job> jobs, client.ListJobs());
  for (const v1::Job& job : jobs) std::printf("%s\n", JobLine(job).c_str());
  if (jobs.empty()) std::printf("no jobs\n");
  return absl::OkStatus();
}

}  // namespace meshseg::cli
