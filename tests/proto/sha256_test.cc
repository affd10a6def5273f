#include "meshseg/proto/sha256.h"

#include <fstream>

#include <gtest/gtest.h>

#include "scratch_dir.h"

namespace meshseg {
namespace {

TEST(Sha256, MatchesKnownDigests) {
  Sha256 empty;
  EXPECT_EQ(empty.HexDigest(),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  Sha256 abc;
  abc.Update("a");
  abc.Update("bc");
  EXPECT_EQ(abc.HexDigest(), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(FileSha256, HashesTheFileAndReportsMissingOnes) {
  const std::string path = testing_files::ScratchPath("abc.txt");
  std::ofstream(path) << "abc";
  EXPECT_EQ(*FileSha256(path),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(FileSha256(path + ".missing").status().code(), absl::StatusCode::kNotFound);
}

TEST(IsSha256Hex, AcceptsOnly64HexDigits) {
  EXPECT_TRUE(IsSha256Hex(std::string(64, 'A')));
  EXPECT_FALSE(IsSha256Hex(std::string(63, 'a')));
  EXPECT_FALSE(IsSha256Hex(std::string(64, 'g')));
}

}  // namespace
}  // namespace meshseg
