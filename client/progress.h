// File: progress.h
// -----------------------------------------------------------------------------
// Job progress for a person: a bar of the whole job (every stage, weighted by
// its typical share of the time: job_progress.h) with the running stage and
// an ETA, redrawn in place when stderr is a terminal, else plain lines on
// stdout (a line per stage and per quarter of it), so logs and pipes stay
// readable and stderr keeps only errors.
#ifndef MESHSEG_CLIENT_PROGRESS_H_
#define MESHSEG_CLIENT_PROGRESS_H_

#include <string>
#include <string_view>
#include <vector>

#include "client/job_progress.h"
#include "meshseg/v1/service.pb.h"

namespace meshseg::cli {

class ProgressPrinter {
 public:
  ProgressPrinter();
  ~ProgressPrinter();

  // Shows `stage` at `fraction` (0..1).
  void Update(std::string_view stage, double fraction);
  // Shows a server event (queue position, or the running stage).
  void Event(const v1::JobEvent& event);
  // Ends the bar's line and the job's clock.
  void Finish();

  // Wall time of each stage seen, then "total" (offline: since the first
  // report; through a server: "queued", and "total" from the job's times).
  std::vector<StageTime> Timings() const;

 private:
  void Draw(std::string_view stage, double fraction);

  bool tty_;
  bool open_line_ = false;
  std::string stage_;          // of the last line printed
  std::string running_stage_;  // of the last Update
  int quarter_ = -1;
  bool done_printed_ = false;  // the line at job 100% was printed
  JobProgress job_;
  v1::Job last_job_;
};

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_PROGRESS_H_
