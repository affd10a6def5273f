// File: job_progress.h
// -----------------------------------------------------------------------------
// The whole job's progress from the pipeline's (stage, fraction) reports: the
// fraction of the job done, an ETA, and the wall time of each stage. The
// stages, their order and their typical share of a job's time come from
// client/progress_stages.txt (embedded at build time), the same file the
// Python client reads, so both show the same numbers for the same events.
#ifndef MESHSEG_CLIENT_JOB_PROGRESS_H_
#define MESHSEG_CLIENT_JOB_PROGRESS_H_

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/time/time.h"

namespace meshseg::cli {

struct StageWeight {
  std::string name;
  double weight = 0.0;  // share of a typical job's wall time
  bool always = true;   // false: only some jobs run it (reconstruct, remesh)
};

// Wall time of one stage (or a step of the job such as "queued", "total").
struct StageTime {
  std::string stage;
  double seconds = 0.0;
};

// Returns the stages of a progress_stages.txt text: "name weight
// always|sometimes" per line, '#' comments. Errors (INVALID_ARGUMENT): a line
// of another shape, a weight that is not a non-negative number.
absl::StatusOr<std::vector<StageWeight>> ParseStageWeights(absl::string_view text);

// Returns the stages of the embedded progress_stages.txt.
std::vector<StageWeight> DefaultStageWeights();

class JobProgress {
 public:
  explicit JobProgress(std::vector<StageWeight> stages = DefaultStageWeights());

  // Records a report at `now`. A stage reported as "name: step" counts as
  // stage `name`; its steps' fractions are of the step, so only reports of
  // "name" itself move the fraction. A "sometimes" stage joins the plan once
  // reported. Unknown stages leave the fraction as it is.
  void Update(std::string_view stage, double fraction, absl::Time now);
  // Marks the job done at `now`: fraction 1, the running stage ended.
  void Finish(absl::Time now);

  // Fraction of the job done, in [0, 1]; never decreases.
  double overall() const { return overall_; }
  // Time from the first report to `now` or to Finish (zero before it).
  absl::Duration Elapsed(absl::Time now) const;
  // Time left: the time so far scaled by the fraction left,
  // elapsed * (1 - overall) / overall; nullopt until at least kMinOverall of
  // the job and kMinElapsed have passed.
  std::optional<absl::Duration> Eta(absl::Time now) const;
  // Wall time of each stage seen, in pipeline order: the sum of the spans
  // it was the running stage (a stage can run again, as remesh inside
  // reconstruct); the running one counts up to `now`.
  std::vector<StageTime> StageTimes(absl::Time now) const;

  static constexpr double kMinOverall = 0.02;
  static constexpr absl::Duration kMinElapsed = absl::Milliseconds(500);

 private:
  double PlannedFraction() const;

  std::vector<StageWeight> stages_;
  std::set<std::string, std::less<>> seen_;
  std::optional<absl::Time> start_;
  std::optional<absl::Time> end_;
  int current_ = -1;  // index into stages_
  double fraction_ = 0.0;
  double overall_ = 0.0;
  absl::Time current_since_;                  // when stages_[current_] last started
  std::map<int, absl::Duration> stage_time_;  // closed spans per stage
};

// Returns "0:07", "12:34" or "1:02:03".
std::string DurationText(absl::Duration d);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_JOB_PROGRESS_H_
