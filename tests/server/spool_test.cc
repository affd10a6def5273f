#include "server/spool.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "scratch_dir.h"

namespace meshseg::server {
namespace {

namespace fs = std::filesystem;

std::string Dir() {
  const fs::path dir =
      testing_files::ScratchPath(::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  return dir.string();
}

JobRecord Record(const std::string& id, int64_t sequence) {
  JobRecord record;
  record.set_format_version(kRecordFormat);
  record.set_sequence(sequence);
  record.mutable_job()->set_job_id(id);
  record.mutable_job()->set_state(v1::JOB_STATE_QUEUED);
  return record;
}

TEST(SafeFileName, DropsDirectoriesAndUnsafeCharacters) {
  EXPECT_EQ(SafeFileName("../../etc/passwd"), "passwd");
  EXPECT_EQ(SafeFileName("C:\\parts\\my part.stl"), "my_part.stl");
  EXPECT_EQ(SafeFileName(".hidden.obj"), "upload.hidden.obj");
  EXPECT_EQ(SafeFileName(""), "upload");
  EXPECT_EQ(SafeFileName(std::string(300, 'a')).size(), 100u);
}

// Two servers on one spool would both recover and run its jobs.
TEST(Spool, ASecondOpenOfTheSameSpoolIsRefusedUntilTheFirstCloses) {
  const std::string dir = Dir();
  absl::StatusOr<std::unique_ptr<Spool>> first = Spool::Open(dir);
  ASSERT_TRUE(first.ok()) << first.status();
  const absl::StatusOr<std::unique_ptr<Spool>> second = Spool::Open(dir);
  EXPECT_EQ(second.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(second.status().message().find("in use by another meshseg-server"),
            absl::string_view::npos)
      << second.status();
  first->reset();
  EXPECT_TRUE(Spool::Open(dir).ok());
}

// Records come back in acceptance order; folders without a usable record
// are reported with the reason and left on disk; files in transit are gone.
TEST(Spool, RecoverReadsRecordsInOrderAndSkipsWhatItCannotRead) {
  const std::string dir = Dir();
  {
    const std::unique_ptr<Spool> spool = *Spool::Open(dir);
    ASSERT_TRUE(spool->WriteRecord(Record("job-b", 2)).ok());
    ASSERT_TRUE(spool->WriteRecord(Record("job-a", 1)).ok());
    JobRecord newer = Record("job-newer", 3);
    newer.set_format_version(kRecordFormat + 1);
    ASSERT_TRUE(spool->WriteRecord(newer).ok());
    std::ofstream(spool->ScratchPath("job-c", "part.stl")) << "half an upload";
  }
  fs::create_directories(fs::path(dir) / "job-old");  // an older server's folder
  std::ofstream(fs::path(dir) / "job-old" / "x.stl") << "x";
  fs::create_directories(fs::path(dir) / "job-corrupt");
  std::ofstream(fs::path(dir) / "job-corrupt" / "#record.pb") << "\xff\xff\xff not a proto";
  std::ofstream(fs::path(dir) / "keep.txt") << "not ours";

  const std::unique_ptr<Spool> spool = *Spool::Open(dir);
  const Spool::Recovered found = spool->Recover();
  ASSERT_EQ(found.records.size(), 2u);
  EXPECT_EQ(found.records[0].job().job_id(), "job-a");
  EXPECT_EQ(found.records[1].job().job_id(), "job-b");
  std::map<std::string, std::string> skipped;
  for (const Spool::Skipped& s : found.skipped) skipped[s.folder] = s.reason;
  EXPECT_EQ(skipped.size(), 3u);
  EXPECT_NE(skipped["job-old"].find("no job record"), std::string::npos);
  EXPECT_NE(skipped["job-corrupt"].find("corrupt"), std::string::npos);
  EXPECT_NE(skipped["job-newer"].find("newer than this server"), std::string::npos);
  EXPECT_TRUE(fs::exists(fs::path(dir) / "job-old" / "x.stl")) << "reported, never deleted";
  EXPECT_TRUE(fs::exists(fs::path(dir) / "keep.txt"));
  EXPECT_EQ(spool->FileCount(), 1) << "job-old's file only; the scratch file is gone";
}

TEST(Spool, RemoveJobRemovesSymlinksWithoutFollowingThem) {
  const std::string dir = Dir();
  const std::string outside = Dir() + "_outside";
  fs::create_directories(outside);
  std::ofstream(fs::path(outside) / "precious.txt") << "keep";
  const std::unique_ptr<Spool> spool = *Spool::Open(dir);
  ASSERT_TRUE(spool->WriteRecord(Record("job-1", 1)).ok());
  fs::create_directory_symlink(outside, fs::path(dir) / "job-1" / "link");
  spool->RemoveJob("job-1");
  EXPECT_FALSE(fs::exists(fs::path(dir) / "job-1"));
  EXPECT_TRUE(fs::exists(fs::path(outside) / "precious.txt"));
}

}  // namespace
}  // namespace meshseg::server
