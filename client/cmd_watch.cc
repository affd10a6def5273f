// meshseg watch JOB [--server HOST:PORT]: progress until the job ends; fails
// with the job's error if it does not succeed.
#include <cstdio>

#include "client/commands.h"
#include "client/progress.h"
#include "client/report.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunWatch(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"--server"}, {}, 1));
  MESHSEG_ASSIGN_OR_RETURN(MeshsegClient client, ConnectFromArgs(args));
  ProgressPrinter progress;
  MESHSEG_ASSIGN_OR_RETURN(
      const v1::Job job,
      client.Watch(args.positional(0), [&](const v1::JobEvent& e) { progress.Event(e); }));
  progress.Finish();
  if (job.state() != v1::JOB_STATE_SUCCEEDED) {
    return absl::Status(static_cast<absl::StatusCode>(job.error_code() ? job.error_code() : 2),
                        JobLine(job));
  }
  std::printf("%s\n", JobLine(job).c_str());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
