// The embedded store's record shelf: records round-trip, the summary kept
// beside each record answers request ids and expiry, and the records take
// their memory from pages of their own, not from malloc's heap.
#include "server/record_shelf.h"

#include <gtest/gtest.h>

#include "server/heap.h"
#include "server/job_store.h"

namespace meshseg::server {
namespace {

JobRecord Record(const std::string& id, v1::JobState state, int64_t finished_unix_ms = 0) {
  JobRecord record;
  record.mutable_job()->set_job_id(id);
  record.mutable_job()->set_state(state);
  record.mutable_job()->set_finished_unix_ms(finished_unix_ms);
  record.mutable_job()->set_file_name("bracket_scan_with_a_long_name.stl");
  record.mutable_job()->set_result_sha256(std::string(64, 'a'));
  record.set_upload_key(id + "/bracket_scan_with_a_long_name.stl");
  return record;
}

TEST(RecordShelf, PutGetReplaceEraseAndVisitInIdOrder) {
  RecordShelf shelf;
  shelf.Put(Record("job-b", v1::JOB_STATE_QUEUED));
  shelf.Put(Record("job-a", v1::JOB_STATE_RUNNING));
  EXPECT_FALSE(shelf.Get("job-c").has_value());
  ASSERT_TRUE(shelf.Get("job-b").has_value());
  EXPECT_EQ(shelf.Get("job-b")->upload_key(), "job-b/bracket_scan_with_a_long_name.stl");

  shelf.Put(Record("job-b", v1::JOB_STATE_SUCCEEDED, 1000));
  EXPECT_EQ(shelf.size(), 2u);
  EXPECT_EQ(shelf.Get("job-b")->job().state(), v1::JOB_STATE_SUCCEEDED);

  std::vector<std::string> ids;
  shelf.ForEach([&](const JobRecord& r) { ids.push_back(r.job().job_id()); });
  EXPECT_EQ(ids, (std::vector<std::string>{"job-a", "job-b"}));

  EXPECT_TRUE(shelf.Erase("job-a"));
  EXPECT_FALSE(shelf.Erase("job-a"));
  EXPECT_FALSE(shelf.Get("job-a").has_value());
  EXPECT_EQ(shelf.size(), 1u);
}

TEST(RecordShelf, FindsRequestsPerTenantAndFinishedJobsBeforeTheCutoff) {
  RecordShelf shelf;
  JobRecord mine = Record("job-1", v1::JOB_STATE_SUCCEEDED, 500);
  mine.mutable_job()->set_tenant("acme");
  mine.mutable_job()->set_request_id("req-7");
  shelf.Put(mine);
  shelf.Put(Record("job-2", v1::JOB_STATE_FAILED, 1500));
  shelf.Put(Record("job-3", v1::JOB_STATE_RUNNING));  // not finished: never expires
  shelf.Put(Record("job-4", v1::JOB_STATE_CANCELLED, 900));

  EXPECT_EQ(shelf.FindRequest("acme", "req-7"), "job-1");
  EXPECT_FALSE(shelf.FindRequest("other", "req-7").has_value());
  EXPECT_FALSE(shelf.FindRequest("acme", "").has_value());
  EXPECT_EQ(shelf.FinishedBefore(1000), (std::vector<std::string>{"job-1", "job-4"}));
  EXPECT_EQ(shelf.FinishedBefore(2000), (std::vector<std::string>{"job-1", "job-2", "job-4"}));
}

// The mechanism: thousands of kept records add (almost) nothing to malloc's
// memory in use, so none of them sits on an arena page between a job's
// buffers; and the shelf's own pages are reused when records expire.
TEST(RecordShelf, RecordsLiveInPagesOfTheirOwnAndExpiredBlocksAreReused) {
  constexpr int kJobs = 3000;
  const std::optional<HeapUsage> before = ReadHeapUsage();
  if (!before) GTEST_SKIP() << "no mallinfo2 on this C library";
  RecordShelf shelf;
  int64_t serialized = 0;
  for (int i = 0; i < kJobs; ++i) {
    const JobRecord record = Record("job-" + std::to_string(i), v1::JOB_STATE_SUCCEEDED, i);
    serialized += static_cast<int64_t>(record.ByteSizeLong());
    shelf.Put(record);
  }
  const HeapUsage after = *ReadHeapUsage();
  // Stored in the heap, the records would be > 3000 x 200 bytes there.
  EXPECT_LT(after.in_use_bytes - before->in_use_bytes, 64 << 10)
      << "records kept " << serialized << " bytes";
  EXPECT_GE(shelf.mapped_bytes(), serialized);
  EXPECT_LT(shelf.mapped_bytes(), 4 * serialized) << "records should be packed";

  const int64_t peak = shelf.mapped_bytes();
  for (const std::string& id : shelf.FinishedBefore(kJobs)) shelf.Erase(id);
  for (int i = 0; i < kJobs; ++i) {
    shelf.Put(Record("job-again-" + std::to_string(i), v1::JOB_STATE_SUCCEEDED, i));
  }
  EXPECT_LE(shelf.mapped_bytes(), peak + peak / 8) << "expired records' blocks not reused";
}

}  // namespace
}  // namespace meshseg::server
