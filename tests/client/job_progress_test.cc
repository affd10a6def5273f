// JobProgress: the whole job's fraction from (stage, fraction) reports with
// stage weights, the ETA extrapolated from the time so far, stage times; and
// the embedded progress_stages.txt.
#include "client/job_progress.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace meshseg::cli {
namespace {

using ::testing::ElementsAre;
using ::testing::Field;
using ::testing::HasSubstr;

const std::vector<StageWeight> kStages = {{"read", 1.0, true},
                                          {"reconstruct", 4.0, false},
                                          {"remesh", 2.0, false},
                                          {"segment", 5.0, true},
                                          {"topology", 2.0, true}};
const absl::Time kT0 = absl::FromUnixSeconds(1000);

TEST(JobProgress, WeighsOnlyTheStagesTheJobRuns) {
  JobProgress job(kStages);
  job.Update("read", 1.0, kT0);
  EXPECT_DOUBLE_EQ(job.overall(), 1.0 / 8) << "read + segment + topology = 8";
  job.Update("segment", 0.5, kT0 + absl::Seconds(2));
  EXPECT_DOUBLE_EQ(job.overall(), 3.5 / 8);
  const std::optional<absl::Duration> eta = job.Eta(kT0 + absl::Seconds(2));
  ASSERT_TRUE(eta.has_value());
  EXPECT_NEAR(absl::ToDoubleSeconds(*eta), 2.0 * (1 - 3.5 / 8) / (3.5 / 8), 1e-9);
  job.Update("topology", 0.5, kT0 + absl::Seconds(3));
  EXPECT_DOUBLE_EQ(job.overall(), 7.0 / 8);
  job.Finish(kT0 + absl::Seconds(4));
  EXPECT_EQ(job.overall(), 1.0);
  EXPECT_EQ(job.Eta(kT0 + absl::Seconds(9)), absl::ZeroDuration());
  EXPECT_EQ(job.Elapsed(kT0 + absl::Seconds(9)), absl::Seconds(4)) << "the clock stopped";
  EXPECT_THAT(job.StageTimes(kT0 + absl::Seconds(9)),
              ElementsAre(Field(&StageTime::seconds, 2.0), Field(&StageTime::seconds, 1.0),
                          Field(&StageTime::seconds, 1.0)));
}

TEST(JobProgress, StepsOfAStageCountAsThatStage) {
  JobProgress job(kStages);
  job.Update("read", 1.0, kT0);
  job.Update("reconstruct", 0.5, kT0);
  EXPECT_DOUBLE_EQ(job.overall(), 3.0 / 12) << "reconstruct joined the plan";
  job.Update("reconstruct: octree", 0.9, kT0);
  EXPECT_DOUBLE_EQ(job.overall(), 3.0 / 12) << "a step's fraction is of the step";
  job.Update("segment", 0.0, kT0);
  EXPECT_DOUBLE_EQ(job.overall(), 5.0 / 12);
  EXPECT_THAT(job.StageTimes(kT0),
              ElementsAre(Field(&StageTime::stage, "read"), Field(&StageTime::stage, "reconstruct"),
                          Field(&StageTime::stage, "segment")));
}

TEST(JobProgress, AStageThatRunsAgainAddsItsSpans) {
  JobProgress job(kStages);
  job.Update("reconstruct", 0.0, kT0);
  job.Update("remesh", 0.0, kT0 + absl::Seconds(1));  // a remesh inside reconstruct
  job.Update("reconstruct", 0.9, kT0 + absl::Seconds(3));
  job.Update("segment", 0.0, kT0 + absl::Seconds(4));
  EXPECT_THAT(job.StageTimes(kT0 + absl::Seconds(6)),
              ElementsAre(Field(&StageTime::seconds, 2.0), Field(&StageTime::seconds, 2.0),
                          Field(&StageTime::seconds, 2.0)))
      << "reconstruct 1 + 1 s, remesh 2 s, segment running for 2 s";
}

TEST(JobProgress, NeverGoesBackAndWaitsBeforeAnEta) {
  JobProgress job(kStages);
  job.Update("segment", 0.8, kT0);
  job.Update("segment", 0.9, kT0 + absl::Milliseconds(100));
  EXPECT_FALSE(job.Eta(kT0 + absl::Milliseconds(100)).has_value()) << "0.1 s is too short";
  const double before = job.overall();
  job.Update("remesh", 0.0, kT0 + absl::Seconds(1));  // a retry on a remesh grows the plan
  EXPECT_EQ(job.overall(), before);
  job.Update("brep", 1.0, kT0 + absl::Seconds(1));  // not in the table
  EXPECT_EQ(job.overall(), before);
}

TEST(ParseStageWeights, ReadsTheEmbeddedFileInPipelineOrder) {
  const std::vector<StageWeight> stages = DefaultStageWeights();
  ASSERT_GE(stages.size(), 4u);
  EXPECT_EQ(stages.front().name, "read");
  for (const StageWeight& s : stages) EXPECT_GT(s.weight, 0.0) << s.name;
}

TEST(ParseStageWeights, BadLineNamesItsNumber) {
  for (const char* text :
       {"read 1 always\nsegment x always\n", "read 1 often\n", "read -1 always\n", "read 1\n"}) {
    const absl::StatusOr<std::vector<StageWeight>> stages = ParseStageWeights(text);
    ASSERT_FALSE(stages.ok()) << text;
    EXPECT_EQ(stages.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_THAT(stages.status().message(), HasSubstr("line "));
  }
}

TEST(DurationText, MinutesAndHours) {
  EXPECT_EQ(DurationText(absl::Seconds(7)), "0:07");
  EXPECT_EQ(DurationText(absl::Seconds(754)), "12:34");
  EXPECT_EQ(DurationText(absl::Seconds(3723)), "1:02:03");
  EXPECT_EQ(DurationText(-absl::Seconds(3)), "0:00");
}

}  // namespace
}  // namespace meshseg::cli
