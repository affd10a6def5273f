#include "server/dir_blob_store.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_dir.h"

namespace meshseg::server {
namespace {

namespace fs = std::filesystem;

std::string Dir(const std::string& suffix) {
  const fs::path dir = testing_files::ScratchPath(
      std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + suffix);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string Read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DirBlobStore, PutOpenRemoveRoundTripAndTheFolderGoesWithTheLastBlob) {
  const std::string dir = Dir("");
  const std::string local = Dir("_local") + "/upload.stl";
  std::ofstream(local) << "solid x";
  auto store = *DirBlobStore::Create(dir);
  ASSERT_TRUE(store->Put("job-1/part.stl", local).ok());
  EXPECT_FALSE(fs::exists(local)) << "Put consumes the local file";
  const absl::StatusOr<std::unique_ptr<LocalBlob>> blob = store->Open("job-1/part.stl");
  ASSERT_TRUE(blob.ok()) << blob.status();
  EXPECT_EQ((*blob)->size(), 7);
  EXPECT_EQ(Read((*blob)->path()), "solid x");
  EXPECT_EQ(store->Open("job-1/none").status().code(), absl::StatusCode::kNotFound);
  ASSERT_TRUE(store->Remove("job-1/part.stl").ok());
  EXPECT_TRUE(store->Remove("job-1/part.stl").ok()) << "removing twice is fine";
  EXPECT_FALSE(fs::exists(fs::path(dir) / "job-1"));
}

TEST(WriteFileAtomically, ReplacesTheWholeFileAndLeavesNoTempFile) {
  const std::string dir = Dir("");
  const std::string path = dir + "/record.pb";
  ASSERT_TRUE(WriteFileAtomically(path, "first").ok());
  ASSERT_TRUE(WriteFileAtomically(path, "second, longer").ok());
  EXPECT_EQ(Read(path), "second, longer");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(WriteFileAtomically, AMissingFolderIsAnErrorNamingThePath) {
  const absl::Status s = WriteFileAtomically(Dir("") + "/no/such/folder/x", "x");
  EXPECT_EQ(s.code(), absl::StatusCode::kInternal);
  EXPECT_NE(s.message().find("no/such/folder/x"), absl::string_view::npos) << s;
}

}  // namespace
}  // namespace meshseg::server
