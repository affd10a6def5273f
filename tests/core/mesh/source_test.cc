#include "mesh/source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "temp_file.h"

namespace meshseg::mesh_internal {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;

const Source kSrc{"read_mesh", "part.off"};

TEST(FileName, DropsDirectories) {
  EXPECT_EQ(FileName("/a/b/bracket.stl"), "bracket.stl");
  EXPECT_EQ(FileName("bracket.stl"), "bracket.stl");
}

TEST(BadInput, NamesOperationAndFile) {
  const absl::Status status = BadInput(kSrc, "line 3: broken");
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(Message(status), "read_mesh: \"part.off\": line 3: broken");
}

TEST(ReadFileBytes, MapsWholeFile) {
  const std::string path = testing_files::WriteTemp("bytes.bin", std::string("ab\0cd", 5));
  absl::StatusOr<FileBytes> bytes = ReadFileBytes(path, kSrc);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  EXPECT_EQ(bytes->view(), std::string_view("ab\0cd", 5));
  FileBytes moved = std::move(*bytes);
  EXPECT_EQ(moved.view().size(), 5u);
}

TEST(ReadFileBytes, ReadsEmptyFile) {
  const absl::StatusOr<FileBytes> bytes = ReadFileBytes(testing_files::WriteTemp("e", ""), kSrc);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  EXPECT_TRUE(bytes->view().empty());
}

TEST(ReadFileBytes, RejectsMissingFileAndDirectory) {
  EXPECT_EQ(ReadFileBytes("/nonexistent/x", kSrc).status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(ReadFileBytes("/tmp", kSrc).status().code(), absl::StatusCode::kInvalidArgument);
}

TEST(CheckDeclaredCount, ChecksLimitAndFileSize) {
  EXPECT_TRUE(CheckDeclaredCount(kSrc, "faces", 10, 8, 80, 100).ok());
  EXPECT_THAT(Message(CheckDeclaredCount(kSrc, "faces", 11, 8, 80, 100)),
              HasSubstr("header declares 11 faces (at least 8 bytes each), but only 80 bytes"));
  EXPECT_THAT(Message(CheckDeclaredCount(kSrc, "faces", 101, 0, 1 << 30, 100)),
              HasSubstr("header declares 101 faces, over the limit of 100"));
  EXPECT_THAT(Message(CheckDeclaredCount(kSrc, "faces", -1, 8, 80, 100)),
              HasSubstr("negative faces count -1"));
}

}  // namespace
}  // namespace meshseg::mesh_internal
