// File: progress.h
// -----------------------------------------------------------------------------
// Job progress for a person: a bar redrawn in place when stderr is a
// terminal, else plain lines on stdout (a line per stage and per quarter),
// so logs and pipes stay readable and stderr keeps only errors.
#ifndef MESHSEG_CLIENT_PROGRESS_H_
#define MESHSEG_CLIENT_PROGRESS_H_

#include <string>
#include <string_view>

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
  // Ends the bar's line.
  void Finish();

 private:
  bool tty_;
  bool open_line_ = false;
  std::string stage_;
  int quarter_ = -1;
};

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_PROGRESS_H_
