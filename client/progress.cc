#include "client/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace meshseg::cli {

ProgressPrinter::ProgressPrinter() : tty_(isatty(fileno(stderr)) != 0) {}

ProgressPrinter::~ProgressPrinter() { Finish(); }

void ProgressPrinter::Update(std::string_view stage, double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (tty_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%s%s] %-12.*s %3.0f%%", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), static_cast<int>(stage.size()),
                 stage.data(), 100.0 * fraction);
    std::fflush(stderr);
    open_line_ = true;
    return;
  }
  const int quarter = static_cast<int>(fraction * 4.0);
  if (stage == stage_ && quarter == quarter_) return;
  stage_ = std::string(stage);
  quarter_ = quarter;
  std::printf("progress: %s %.0f%%\n", stage_.c_str(), 100.0 * fraction);
  std::fflush(stdout);
}

void ProgressPrinter::Event(const v1::JobEvent& event) {
  const v1::Job& job = event.job();
  if (job.state() == v1::JOB_STATE_QUEUED) {
    Update("queued", 0.0);
  } else if (job.state() == v1::JOB_STATE_RUNNING && !job.stage().empty()) {
    Update(job.stage(), job.fraction());
  } else if (job.state() == v1::JOB_STATE_SUCCEEDED) {
    // The watch stream reports the latest state only and may skip the last
    // running step: close the bar at 100 %.
    Update(stage_.empty() ? std::string("done") : stage_, 1.0);
  }
}

void ProgressPrinter::Finish() {
  if (tty_ && open_line_) std::fputc('\n', stderr);
  open_line_ = false;
}

}  // namespace meshseg::cli
