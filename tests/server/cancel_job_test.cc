#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

class CancelJobTest : public ::testing::Test {
 protected:
  CancelJobTest() : server_({.workers = 1, .runner = gate_.Runner()}) {
    path_ = FreshDir("files") + "/box.off";
    testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path_);
  }
  Gate gate_;
  TestServer server_;
  std::string path_;
};

TEST_F(CancelJobTest, CancelMidRunStopsTheJobPromptlyAndFreesItsWorker) {
  MeshsegClient client = server_.Client();
  const std::string running = client.Upload(path_)->job_id();
  const std::string next = client.Upload(path_)->job_id();
  ASSERT_TRUE(Eventually([&] { return client.GetJob(running)->state() == v1::JOB_STATE_RUNNING; }));
  ASSERT_TRUE(client.Cancel(running).ok());
  const absl::StatusOr<v1::Job> job = client.Watch(running);
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  // The single worker moves on to the next job.
  ASSERT_TRUE(Eventually([&] { return gate_.entered == 2; }));
  gate_.open.Notify();
  EXPECT_EQ(client.Watch(next)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(Eventually([&] { return server_.SpoolFiles() == 1; })) << "only the finished job's result";
}

TEST_F(CancelJobTest, CancelQueuedJobNeverRunsIt) {
  MeshsegClient client = server_.Client();
  const std::string running = client.Upload(path_)->job_id();
  const std::string queued = client.Upload(path_)->job_id();
  const absl::StatusOr<v1::Job> job = client.Cancel(queued);
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  gate_.open.Notify();
  EXPECT_EQ(client.Watch(running)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(gate_.entered, 1);
  EXPECT_EQ(client.Cancel(running).status().code(), absl::StatusCode::kFailedPrecondition);
}

TEST_F(CancelJobTest, UnknownJobIsNotFound) {
  MeshsegClient client = server_.Client();
  EXPECT_EQ(client.Cancel("job-0000000000000000").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.GetJob("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Result("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Watch("nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(std::string(client.GetJob("nope").status().message()), ::testing::HasSubstr("nope"));
  gate_.open.Notify();
}

// The real pipeline, stopped mid-run: the runner holds the job inside its
// first "curvature" progress report until the cancel arrives. "Promptly" is
// checked without a clock: after the stop request the pipeline reports no
// later stage (segment, topology) and ends CANCELLED.
TEST(CancelJob, RealPipelineStopsAtTheNextCheckAndFreesItsWorker) {
  absl::Mutex mu;
  bool stop_seen = false;
  std::vector<std::string> stages_after_stop;
  std::atomic<bool> held{false};
  std::atomic<int> jobs{0};
  const server::JobRunner runner = [&](const std::string& path, const PipelineParams& params,
                                       const RunContext& ctx) {
    if (jobs.fetch_add(1) > 0) return RunPipeline(path, params, ctx);  // only the first is held
    RunContext inner = ctx;
    inner.on_progress = [&](std::string_view stage, double fraction) {
      ctx.Progress(stage, fraction);
      bool hold = false;
      {
        absl::MutexLock lock(&mu);
        if (stop_seen) stages_after_stop.emplace_back(stage);
        hold = stage == "curvature" && !held.exchange(true);
      }
      if (!hold) return;
      while (!ctx.stop_requested()) absl::SleepFor(absl::Milliseconds(1));
      absl::MutexLock lock(&mu);
      stop_seen = true;
    };
    // The box is an exact tessellation, segmented facet by facet without a
    // curvature stage; the held job takes the scan path, which has one.
    PipelineParams scan = params;
    scan.segment.exact = ExactMode::kNever;
    return RunPipeline(path, scan, inner);
  };
  TestServer server({.workers = 1, .runner = runner});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(4, {2, 1, 1}), path);
  const std::string running = client.Upload(path)->job_id();
  const std::string next = client.Upload(path)->job_id();
  ASSERT_TRUE(Eventually([&] { return held.load(); }));
  EXPECT_EQ(client.GetJob(running)->stage(), "curvature");
  ASSERT_TRUE(client.Cancel(running).ok());
  const absl::StatusOr<v1::Job> job = client.Watch(running);
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(job->error_code(), static_cast<int>(absl::StatusCode::kCancelled));
  {
    absl::MutexLock lock(&mu);
    EXPECT_TRUE(stop_seen);
    for (const std::string& stage : stages_after_stop) {
      EXPECT_TRUE(stage.rfind("curvature", 0) == 0) << "stage " << stage << " ran after the stop";
    }
  }
  // The worker is free: the next job runs the whole pipeline.
  const absl::StatusOr<v1::Job> second = client.Watch(next);
  ASSERT_TRUE(second.ok()) << second.status();
  EXPECT_EQ(second->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(second->face_count(), 4 * 4 * 12);
  // The upload goes once the outcome is recorded, a moment after the client saw it.
  EXPECT_TRUE(Eventually([&] { return server.SpoolFiles() == 1; }))
      << "only the finished job's result";
}

}  // namespace
}  // namespace meshseg
