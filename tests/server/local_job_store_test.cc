// The embedded job store: the state machine, attempts, and that every state
// change is on disk, so a new store over the same spool recovers it.
#include "server/local_job_store.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scratch_dir.h"
#include "server/heap.h"
#include "server/in_memory_job_queue.h"

namespace meshseg::server {
namespace {

JobRecord NewRecord(const std::string& file = "part.stl") {
  JobRecord record;
  const std::string id = NewJobId();
  record.mutable_job()->set_job_id(id);
  record.mutable_job()->set_file_name(file);
  record.mutable_job()->set_upload_size(100);
  record.set_upload_key(UploadKey(id, file));
  return record;
}

class LocalJobStoreTest : public ::testing::Test {
 protected:
  LocalJobStoreTest()
      : dir_(testing_files::ScratchPath(
            ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    std::filesystem::remove_all(dir_);
    Reopen();
  }

  // A new store over the same spool, as after a restart.
  LocalJobStore::Recovery Reopen(absl::Time cutoff = absl::InfinitePast()) {
    store_.reset();
    queue_.reset();
    spool_.reset();
    spool_ = *Spool::Open(dir_);
    queue_ = std::make_unique<InMemoryJobQueue>(8);
    store_ = std::make_unique<LocalJobStore>(*queue_, *spool_);
    LocalJobStore::Recovery found = store_->Recover(cutoff);
    queue_->Restore(found.requeue);
    return found;
  }

  std::string AddQueued() {
    const JobRecord record = NewRecord();
    EXPECT_TRUE(store_->Create(record).ok());
    EXPECT_TRUE(queue_->Push(record.job().job_id()).ok());
    return record.job().job_id();
  }

  std::string dir_;
  std::unique_ptr<Spool> spool_;
  std::unique_ptr<InMemoryJobQueue> queue_;
  std::unique_ptr<LocalJobStore> store_;
};

TEST_F(LocalJobStoreTest, WalksQueuedRunningSucceeded) {
  const std::string id = AddQueued();
  EXPECT_EQ(store_->Get(id)->state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(store_->Get(id)->queue_position(), 0);
  ASSERT_EQ(queue_->Pop()->job_id, id);
  const absl::StatusOr<JobStore::Started> started = store_->Start(id, 3);
  ASSERT_TRUE(started.ok());
  ASSERT_EQ(started->outcome, JobStore::StartOutcome::kRun);
  EXPECT_EQ(started->spec.record.upload_key(), id + "/part.stl");
  EXPECT_EQ(store_->Get(id)->attempts(), 1);
  store_->Progress(id, "read", 0.5);
  EXPECT_EQ(store_->Get(id)->stage(), "read");
  EXPECT_EQ(store_->Get(id)->queue_position(), -1);
  ASSERT_TRUE(
      store_->Finish(id, absl::OkStatus(), {.result_size = 42, .face_count = 12, .region_count = 3})
          .ok());
  const v1::Job job = *store_->Get(id);
  EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(job.result_size(), 42);
  EXPECT_EQ(job.region_count(), 3);
  EXPECT_GT(job.finished_unix_ms(), 0);
}

TEST_F(LocalJobStoreTest, FailedJobKeepsCodeAndMessage) {
  const std::string id = AddQueued();
  ASSERT_EQ(store_->Start(id, 3)->outcome, JobStore::StartOutcome::kRun);
  ASSERT_TRUE(store_->Finish(id, absl::InvalidArgumentError("read_mesh: \"x.stl\": nan"), {}).ok());
  const v1::Job job = *store_->Get(id);
  EXPECT_EQ(job.state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(job.error_code(), static_cast<int>(absl::StatusCode::kInvalidArgument));
  EXPECT_EQ(job.error_message(), "read_mesh: \"x.stl\": nan");
}

TEST_F(LocalJobStoreTest, CancelQueuedIsImmediateAndRunningRequestsStop) {
  const std::string queued = AddQueued();
  const std::string running = AddQueued();
  const absl::StatusOr<JobStore::Started> started = store_->Start(running, 3);
  ASSERT_EQ(started->outcome, JobStore::StartOutcome::kRun);
  EXPECT_EQ(*store_->Cancel(queued, "bye"), JobStore::CancelOutcome::kWasQueued);
  EXPECT_EQ(store_->Get(queued)->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(store_->Start(queued, 3)->outcome, JobStore::StartOutcome::kNotRunnable)
      << "a cancelled job must not run";
  EXPECT_EQ(*store_->Cancel(running, "bye"), JobStore::CancelOutcome::kStopRequested);
  EXPECT_TRUE(started->spec.stop.stop_requested());
  ASSERT_TRUE(store_->Finish(running, absl::CancelledError("stopped"), {}).ok());
  EXPECT_EQ(store_->Get(running)->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(store_->Cancel(running, "again").status().code(),
            absl::StatusCode::kFailedPrecondition);
}

TEST_F(LocalJobStoreTest, UnknownIdIsNotFound) {
  EXPECT_EQ(store_->Get("job-nope").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(store_->Cancel("job-nope", "x").status().code(), absl::StatusCode::kNotFound);
}

TEST_F(LocalJobStoreTest, ExpireForgetsOnlyFinishedJobsOlderThanTheCutoffAndTheirFolders) {
  const std::string done = AddQueued();
  const std::string waiting = AddQueued();
  ASSERT_EQ(store_->Start(done, 3)->outcome, JobStore::StartOutcome::kRun);
  ASSERT_TRUE(store_->Finish(done, absl::OkStatus(), {}).ok());
  EXPECT_TRUE(store_->Expire(absl::Now() - absl::Hours(1)).empty());
  EXPECT_EQ(store_->Expire(absl::Now() + absl::Seconds(1)), std::vector<std::string>{done});
  EXPECT_EQ(store_->Get(done).status().code(), absl::StatusCode::kNotFound);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(dir_) / done));
  EXPECT_TRUE(store_->Get(waiting).ok());
}

TEST_F(LocalJobStoreTest, GenerationGrowsOnEveryChange) {
  const int64_t before = store_->generation();
  const std::string id = AddQueued();
  EXPECT_GT(store_->generation(), before);
  const int64_t after_add = store_->generation();
  ASSERT_TRUE(store_->Start(id, 3).ok());
  store_->AwaitChange(after_add, absl::Seconds(5));  // returns at once
  EXPECT_GT(store_->generation(), after_add);
}

// After a restart: finished jobs are served, queued ones queued again in
// their old order, the interrupted one first in line as QUEUED with its
// attempt kept, and nothing past the TTL.
TEST_F(LocalJobStoreTest, RecoverServesFinishedAndRequeuesTheRestInOrder) {
  const std::string done = AddQueued();
  const std::string interrupted = AddQueued();
  const std::string first = AddQueued();
  const std::string second = AddQueued();
  ASSERT_EQ(store_->Start(done, 3)->outcome, JobStore::StartOutcome::kRun);
  ASSERT_TRUE(store_->Finish(done, absl::OkStatus(), {.result_size = 7}).ok());
  ASSERT_EQ(store_->Start(interrupted, 3)->outcome, JobStore::StartOutcome::kRun);

  const LocalJobStore::Recovery found = Reopen();
  EXPECT_EQ(found.served, 1);
  EXPECT_EQ(found.interrupted, 1);
  EXPECT_EQ(found.requeue, (std::vector<std::string>{interrupted, first, second}));
  EXPECT_EQ(store_->Get(done)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(store_->Get(done)->result_size(), 7);
  const v1::Job again = *store_->Get(interrupted);
  EXPECT_EQ(again.state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(again.attempts(), 1);
  EXPECT_EQ(again.queue_position(), 0);
  EXPECT_EQ(store_->Get(second)->queue_position(), 2);
  EXPECT_EQ(store_->List()->size(), 4u);

  const LocalJobStore::Recovery later = Reopen(absl::Now() + absl::Seconds(1));
  EXPECT_EQ(later.expired, 1);
  EXPECT_EQ(store_->Get(done).status().code(), absl::StatusCode::kNotFound);
}

// A job started max_attempts times (its worker died each time) is given up:
// FAILED with the count, never run again.
TEST_F(LocalJobStoreTest, GivesUpAfterMaxAttempts) {
  const std::string id = AddQueued();
  for (int attempt = 1; attempt <= 2; ++attempt) {
    ASSERT_EQ(store_->Start(id, 2)->outcome, JobStore::StartOutcome::kRun);
    Reopen();  // the worker died: the job is queued again
    EXPECT_EQ(store_->Get(id)->attempts(), attempt);
  }
  const absl::StatusOr<JobStore::Started> last = store_->Start(id, 2);
  ASSERT_TRUE(last.ok());
  EXPECT_EQ(last->outcome, JobStore::StartOutcome::kGaveUp);
  const v1::Job job = *store_->Get(id);
  EXPECT_EQ(job.state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(job.error_code(), static_cast<int>(absl::StatusCode::kAborted));
  EXPECT_EQ(job.error_message(),
            "worker died 2 times running this job (--max-attempts 2); not run again");
  Reopen();
  EXPECT_EQ(store_->Get(id)->state(), v1::JOB_STATE_FAILED) << "the verdict is on disk";
}

// A job stopped by a shutdown goes back to QUEUED and its attempt is not
// counted against it.
TEST_F(LocalJobStoreTest, ReleaseRequeuesWithoutCountingTheAttempt) {
  const std::string id = AddQueued();
  ASSERT_EQ(store_->Start(id, 3)->outcome, JobStore::StartOutcome::kRun);
  ASSERT_TRUE(store_->Release(id).ok());
  EXPECT_EQ(store_->Get(id)->state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(store_->Get(id)->attempts(), 0);
  EXPECT_EQ(Reopen().requeue, std::vector<std::string>{id});
}

// A finished job's record is kept for the result TTL, but not in malloc's
// heap, where each record would sit between the job buffers of the threads
// that changed it and keep their pages resident after the buffers are freed.
TEST_F(LocalJobStoreTest, FinishedJobsKeepNothingInMallocsHeap) {
  constexpr int kJobs = 24;
  std::vector<std::string> ids;
  for (int i = 0; i < kJobs; ++i) ids.push_back(NewRecord().job().job_id());
  const std::optional<HeapUsage> before = ReadHeapUsage();
  if (!before) GTEST_SKIP() << "no mallinfo2 on this C library";
  for (const std::string& id : ids) {
    JobRecord record = NewRecord();
    record.mutable_job()->set_job_id(id);
    record.set_upload_key(UploadKey(id, "part.stl"));
    ASSERT_TRUE(store_->Create(record).ok());
    ASSERT_EQ(store_->Start(id, 3)->outcome, JobStore::StartOutcome::kRun);
    store_->Progress(id, "segment", 0.5);
    const JobOutput output{.result_size = 4242,
                           .result_sha256 = std::string(64, 'f'),
                           .face_count = 1200,
                           .region_count = 7};
    ASSERT_TRUE(store_->Finish(id, absl::OkStatus(), output).ok());
  }
  const HeapUsage after = *ReadHeapUsage();
  // In the heap, 24 records of ~1 KB (the record's message and its strings)
  // would add ~24 KiB.
  EXPECT_LT(after.in_use_bytes - before->in_use_bytes, 8 << 10)
      << "heap in use grew by " << after.in_use_bytes - before->in_use_bytes << " bytes";
  const v1::Job last = *store_->Get(ids.back());
  EXPECT_EQ(last.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(last.result_sha256(), std::string(64, 'f'));
  EXPECT_EQ(store_->List()->size(), static_cast<size_t>(kJobs));
}

}  // namespace
}  // namespace meshseg::server
