#include "client/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "absl/time/clock.h"

namespace meshseg::cli {
namespace {

std::string EtaText(const JobProgress& job, absl::Time now) {
  const std::optional<absl::Duration> eta = job.Eta(now);
  return eta ? DurationText(*eta) : std::string("--:--");
}

}  // namespace

ProgressPrinter::ProgressPrinter() : tty_(isatty(fileno(stderr)) != 0) {}

ProgressPrinter::~ProgressPrinter() { Finish(); }

void ProgressPrinter::Update(std::string_view stage, double fraction) {
  job_.Update(stage, fraction, absl::Now());
  running_stage_ = std::string(stage);
  Draw(stage, fraction);
}

void ProgressPrinter::Draw(std::string_view stage, double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const absl::Time now = absl::Now();
  const double overall = job_.overall();
  if (tty_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(overall * kWidth);
    // \033[K clears what a longer previous line left behind.
    std::fprintf(stderr, "\r[%s%s] %-12.*s %3.0f%%  job %3.0f%%  ETA %s\033[K",
                 std::string(filled, '#').c_str(), std::string(kWidth - filled, ' ').c_str(),
                 static_cast<int>(stage.size()), stage.data(), 100.0 * fraction, 100.0 * overall,
                 EtaText(job_, now).c_str());
    std::fflush(stderr);
    open_line_ = true;
    return;
  }
  const int quarter = static_cast<int>(fraction * 4.0);
  // The job's end gets its line even when its stage's last quarter had one.
  const bool done = overall >= 1.0 && !done_printed_;
  if (stage == stage_ && quarter == quarter_ && !done) return;
  done_printed_ = done_printed_ || done;
  stage_ = std::string(stage);
  quarter_ = quarter;
  std::printf("progress: %s %.0f%% (job %.0f%%, ETA %s)\n", stage_.c_str(), 100.0 * fraction,
              100.0 * overall, EtaText(job_, now).c_str());
  std::fflush(stdout);
}

void ProgressPrinter::Event(const v1::JobEvent& event) {
  const v1::Job& job = event.job();
  last_job_ = job;
  if (job.state() == v1::JOB_STATE_QUEUED) {
    Draw("queued", 0.0);
  } else if (job.state() == v1::JOB_STATE_RUNNING && !job.stage().empty()) {
    Update(job.stage(), job.fraction());
  } else if (job.state() == v1::JOB_STATE_SUCCEEDED) {
    // The watch stream reports the latest state only and may skip the last
    // running step: close the bar at 100 %.
    job_.Finish(absl::Now());
    Draw(running_stage_.empty() ? std::string("done") : running_stage_, 1.0);
  }
}

void ProgressPrinter::Finish() {
  job_.Finish(absl::Now());
  if (tty_ && open_line_) std::fputc('\n', stderr);
  open_line_ = false;
}

std::vector<StageTime> ProgressPrinter::Timings() const {
  const absl::Time now = absl::Now();
  std::vector<StageTime> times = job_.StageTimes(now);
  const v1::Job& job = last_job_;
  if (job.started_unix_ms() > 0 && job.created_unix_ms() > 0) {
    times.push_back(
        {"queued", 1e-3 * static_cast<double>(job.started_unix_ms() - job.created_unix_ms())});
  }
  if (job.finished_unix_ms() > 0 && job.started_unix_ms() > 0) {
    times.push_back(
        {"total", 1e-3 * static_cast<double>(job.finished_unix_ms() - job.started_unix_ms())});
  } else if (!times.empty()) {
    times.push_back({"total", absl::ToDoubleSeconds(job_.Elapsed(now))});
  }
  return times;
}

}  // namespace meshseg::cli
