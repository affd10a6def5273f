#include "server/spool.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

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

TEST(SafeFileName, DropsDirectoriesAndUnsafeCharacters) {
  EXPECT_EQ(SafeFileName("../../etc/passwd"), "passwd");
  EXPECT_EQ(SafeFileName("C:\\parts\\my part.stl"), "my_part.stl");
  EXPECT_EQ(SafeFileName(".hidden.obj"), "upload.hidden.obj");
  EXPECT_EQ(SafeFileName(""), "upload");
  EXPECT_EQ(SafeFileName(std::string(300, 'a')).size(), 100u);
}

TEST(Spool, OpenClearsJobFoldersAPreviousRunLeft) {
  const std::string dir = Dir();
  fs::create_directories(fs::path(dir) / "job-old");
  std::ofstream(fs::path(dir) / "job-old" / "x.stl") << "x";
  std::ofstream(fs::path(dir) / "keep.txt") << "not ours";
  const absl::StatusOr<Spool> spool = Spool::Open(dir);
  ASSERT_TRUE(spool.ok()) << spool.status();
  EXPECT_FALSE(fs::exists(fs::path(dir) / "job-old"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "keep.txt"));
}

TEST(Spool, CreateJobAndRemoveJobLeaveNothingBehind) {
  const std::string dir = Dir();
  const absl::StatusOr<Spool> spool = Spool::Open(dir);
  ASSERT_TRUE(spool.ok());
  const absl::StatusOr<std::string> path = spool->CreateJob("job-1", "a/b/part.stl");
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_EQ(fs::path(*path).filename(), "part.stl");
  std::ofstream(*path) << "solid";
  std::ofstream(spool->ResultPath("job-1")) << "pb";
  EXPECT_EQ(spool->FileCount(), 2);
  spool->RemoveJob("job-1");
  EXPECT_EQ(spool->FileCount(), 0);
  EXPECT_FALSE(fs::exists(fs::path(dir) / "job-1"));
}

}  // namespace
}  // namespace meshseg::server
