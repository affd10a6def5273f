// The exposition writer and the registry: text format 0.0.4 (HELP/TYPE per
// family, escaped label values, cumulative buckets ending in +Inf, _sum and
// _count), and hooks moving the samples they should.
#include "server/metrics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "server/heap.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(Histogram, CountsEachObservationInTheFirstBucketWhoseBoundHoldsIt) {
  Histogram h({1, 2, 5});
  for (double v : {0.5, 1.0, 1.5, 5.0, 7.0}) h.Observe(v);
  EXPECT_THAT(h.counts(), ::testing::ElementsAre(2, 1, 1, 1));
  EXPECT_EQ(h.count(), 5u);
  EXPECT_DOUBLE_EQ(h.sum(), 15.0);
}

TEST(ExpositionWriter, WritesHelpTypeAndEscapedSamples) {
  ExpositionWriter w;
  w.Family("x_total", "counter", "Help with \\ and\nnewline.");
  w.Sample("x_total", {{"path", "a\"b\\c\nd"}}, 3);
  w.Sample("x_total", {}, 0.25);
  EXPECT_EQ(w.text(),
            "# HELP x_total Help with \\\\ and\\nnewline.\n"
            "# TYPE x_total counter\n"
            "x_total{path=\"a\\\"b\\\\c\\nd\"} 3\n"
            "x_total 0.25\n");
}

TEST(ExpositionWriter, HistogramBucketsAreCumulativeAndEndWithInf) {
  Histogram h({0.1, 1});
  for (double v : {0.05, 0.5, 0.7, 3.0}) h.Observe(v);
  ExpositionWriter w;
  w.HistogramSamples("d_seconds", {{"stage", "fit"}}, h);
  EXPECT_EQ(w.text(),
            "d_seconds_bucket{stage=\"fit\",le=\"0.1\"} 1\n"
            "d_seconds_bucket{stage=\"fit\",le=\"1\"} 3\n"
            "d_seconds_bucket{stage=\"fit\",le=\"+Inf\"} 4\n"
            "d_seconds_sum{stage=\"fit\"} 4.25\n"
            "d_seconds_count{stage=\"fit\"} 4\n");
}

TEST(Metrics, HooksMoveTheirSamples) {
  Metrics& m = Metrics::Global();
  m.ResetForTest();
  m.SetGauges({.queued = [] { return std::optional<int64_t>(7); },
                .running = [] { return int64_t{2}; },
                .admission_reserved_bytes = {}});
  m.UploadAccepted(1000);
  m.UploadAccepted(24);
  m.UploadRejected(absl::StatusCode::kResourceExhausted);
  m.JobStarted(absl::Now() - absl::Seconds(3), 1);
  m.JobStarted(absl::Now() - absl::Seconds(60), 2);  // a retry: no second queue wait
  m.JobClaimed();
  m.StageDone("segment", absl::Milliseconds(20));
  m.StageDone("segment", absl::Milliseconds(30));
  m.StageDone("fit", absl::Seconds(2));
  m.JobFinished("SUCCEEDED", absl::Seconds(4));
  m.JobFinished("CANCELLED", std::nullopt);
  m.ResultWritten(512);
  const std::string text = m.Exposition();
  for (const char* line : {
           "meshseg_jobs_total{state=\"succeeded\"} 1\n",
           "meshseg_jobs_total{state=\"cancelled\"} 1\n",
           "meshseg_jobs_total{state=\"failed\"} 0\n",
           "meshseg_jobs_accepted_total 2\n",
           "meshseg_uploads_rejected_total{code=\"RESOURCE_EXHAUSTED\"} 1\n",
           "meshseg_jobs_queued 7\n",
           "meshseg_jobs_running 2\n",
           "meshseg_upload_bytes_total 1024\n",
           "meshseg_result_bytes_total 512\n",
           "meshseg_worker_attempts_total 2\n",
           "meshseg_worker_claims_total 1\n",
           "meshseg_queue_wait_seconds_count 1\n",
           "meshseg_queue_wait_seconds_bucket{le=\"1\"} 0\n",
           "meshseg_queue_wait_seconds_bucket{le=\"5\"} 1\n",
           "meshseg_job_duration_seconds_count 1\n",
           "meshseg_job_duration_seconds_sum 4\n",
           "meshseg_stage_duration_seconds_count{stage=\"segment\"} 2\n",
           "meshseg_stage_duration_seconds_sum{stage=\"segment\"} 0.05\n",
           "meshseg_stage_duration_seconds_bucket{stage=\"fit\",le=\"1\"} 0\n",
           "meshseg_stage_duration_seconds_count{stage=\"fit\"} 1\n",
           "meshseg_admission_reserved_bytes 0\n",
       }) {
    EXPECT_THAT(text, HasSubstr(line));
  }
  EXPECT_THAT(text, ::testing::ContainsRegex("meshseg_build_info\\{version=\"[0-9.]+\",role=\"[a-z]+\","
                                             "backend=\"[a-z]+\"\\} 1\n"));
  EXPECT_THAT(text, ::testing::ContainsRegex("\nprocess_resident_memory_bytes [1-9][0-9]+\n"));
  if (ReadHeapUsage()) {  // glibc: the heap split into in use and held free
    EXPECT_THAT(text, ::testing::ContainsRegex("\nmeshseg_heap_in_use_bytes [1-9][0-9]+\n"));
    EXPECT_THAT(text, ::testing::ContainsRegex("\nmeshseg_heap_free_bytes [0-9]+\n"));
  }
  m.SetGauges({.queued = [] { return std::optional<int64_t>(); }, .running = {}, .admission_reserved_bytes = {}});
  EXPECT_THAT(m.Exposition(), Not(HasSubstr("\nmeshseg_jobs_queued ")))
      << "an unreachable queue leaves the sample out rather than report 0";
  m.SetGauges({});
  m.ResetForTest();
}

TEST(Metrics, StageNamesPastTheCapCountAsOther) {
  Metrics& m = Metrics::Global();
  m.ResetForTest();
  for (int i = 0; i < 40; ++i) m.StageDone(absl::StrCat("stage", i), absl::Milliseconds(1));
  const std::string text = m.Exposition();
  EXPECT_THAT(text, HasSubstr("meshseg_stage_duration_seconds_count{stage=\"stage0\"} 1\n"));
  EXPECT_THAT(text, HasSubstr("meshseg_stage_duration_seconds_count{stage=\"other\"} 8\n"));
  EXPECT_THAT(text, Not(HasSubstr("stage=\"stage39\"")));
  m.ResetForTest();
}

}  // namespace
}  // namespace meshseg::server
