#include "client/job_progress.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "client/embedded.h"

namespace meshseg::cli {

absl::StatusOr<std::vector<StageWeight>> ParseStageWeights(absl::string_view text) {
  std::vector<StageWeight> stages;
  int line_number = 0;
  for (absl::string_view line : absl::StrSplit(text, '\n')) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    const std::vector<absl::string_view> words =
        absl::StrSplit(line, absl::ByAnyChar(" \t\r"), absl::SkipEmpty());
    if (words.empty()) continue;
    StageWeight stage{.name = std::string(words[0])};
    if (words.size() != 3 || !absl::SimpleAtod(words[1], &stage.weight) || !(stage.weight >= 0.0) ||
        !std::isfinite(stage.weight) || (words[2] != "always" && words[2] != "sometimes")) {
      return absl::InvalidArgumentError(absl::StrCat(
          "progress stages: line ", line_number, " \"", absl::StripAsciiWhitespace(line),
          "\" is not \"name weight always|sometimes\" with a weight >= 0"));
    }
    stage.always = words[2] == "always";
    stages.push_back(std::move(stage));
  }
  return stages;
}

std::vector<StageWeight> DefaultStageWeights() {
  absl::StatusOr<std::vector<StageWeight>> stages = ParseStageWeights(embedded::kProgressStages);
  assert(stages.ok() && "client/progress_stages.txt parses (tested)");
  return stages.ok() ? *std::move(stages) : std::vector<StageWeight>{};
}

JobProgress::JobProgress(std::vector<StageWeight> stages) : stages_(std::move(stages)) {}

void JobProgress::Update(std::string_view stage, double fraction, absl::Time now) {
  if (!start_) start_ = now;
  const absl::string_view head(stage.data(), std::min(stage.size(), stage.find(':')));
  const absl::string_view name = absl::StripAsciiWhitespace(head);
  const auto it = std::find_if(stages_.begin(), stages_.end(),
                               [&](const StageWeight& s) { return s.name == name; });
  if (it == stages_.end()) return;
  const int index = static_cast<int>(it - stages_.begin());
  if (index != current_) {
    if (current_ >= 0) stage_time_[current_] += now - current_since_;
    stage_time_.emplace(index, absl::ZeroDuration());
    current_ = index;
    current_since_ = now;
    fraction_ = 0.0;
  }
  seen_.insert(std::string(name));
  if (name.size() == stage.size()) fraction_ = std::clamp(fraction, 0.0, 1.0);
  overall_ = std::max(overall_, PlannedFraction());
}

void JobProgress::Finish(absl::Time now) {
  if (end_) return;
  if (current_ >= 0) stage_time_[current_] += now - current_since_;
  end_ = now;
  overall_ = 1.0;
}

absl::Duration JobProgress::Elapsed(absl::Time now) const {
  if (!start_) return absl::ZeroDuration();
  return (end_ ? std::min(now, *end_) : now) - *start_;
}

std::optional<absl::Duration> JobProgress::Eta(absl::Time now) const {
  if (overall_ >= 1.0) return absl::ZeroDuration();
  const absl::Duration elapsed = Elapsed(now);
  if (overall_ < kMinOverall || elapsed < kMinElapsed) return std::nullopt;
  return elapsed * ((1.0 - overall_) / overall_);
}

std::vector<StageTime> JobProgress::StageTimes(absl::Time now) const {
  std::vector<StageTime> times;
  for (const auto& [index, closed] : stage_time_) {
    const absl::Duration open =
        index == current_ && !end_ ? now - current_since_ : absl::ZeroDuration();
    times.push_back({stages_[index].name, absl::ToDoubleSeconds(closed + open)});
  }
  return times;
}

// Weight of the stages before the current one plus the current stage's done
// share, over the weight of every stage this job runs: all "always" stages
// and the "sometimes" stages seen.
double JobProgress::PlannedFraction() const {
  double total = 0.0, done = 0.0;
  for (int i = 0; i < static_cast<int>(stages_.size()); ++i) {
    if (!stages_[i].always && !seen_.contains(stages_[i].name)) continue;
    total += stages_[i].weight;
    if (i < current_) done += stages_[i].weight;
  }
  done += stages_[current_].weight * fraction_;
  return total > 0.0 ? std::min(done / total, 1.0) : 0.0;
}

std::string DurationText(absl::Duration d) {
  const int64_t s = std::max<int64_t>(0, absl::ToInt64Seconds(d + absl::Milliseconds(500)));
  if (s >= 3600) return absl::StrFormat("%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
  return absl::StrFormat("%d:%02d", s / 60, s % 60);
}

}  // namespace meshseg::cli
