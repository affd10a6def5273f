// The token file: its format, every way it can be wrong (named by line,
// never quoting the token), bearer-header parsing, and reload keeping the
// old table when the new file is bad.
#include "server/auth.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr char kAlice[] = "alice-token-0123456789";
constexpr char kBob[] = "bob-token-0123456789ab";

TEST(ParseTokenFile, ReadsPairsSkippingCommentsAndBlankLines) {
  const auto table = ParseTokenFile(
      absl::StrCat("# tenants\n\n", kAlice, " alice\n  ", kBob, "\tbob   # ops\r\n"), "t.txt");
  ASSERT_TRUE(table.ok()) << table.status();
  EXPECT_EQ(table->size(), 2u);
}

TEST(ParseTokenFile, NamesTheLineOfEveryMistakeWithoutQuotingTokens) {
  struct Case {
    std::string text;
    std::string message;
  };
  const Case cases[] = {
      {"short tenant\n", "line 1: token of 5 characters, at least 16 needed"},
      {absl::StrCat("# c\n", kAlice, "\n"), "line 2: expected \"TOKEN TENANT\", got 1 words"},
      {absl::StrCat(kAlice, " a b\n"), "line 1: expected \"TOKEN TENANT\", got 3 words"},
      {absl::StrCat(kAlice, " al/ice\n"), "line 1: tenant must be 1-64 characters"},
      {absl::StrCat(kAlice, " ", std::string(65, 't'), "\n"), "line 1: tenant must be"},
      {absl::StrCat(kAlice, " a\n", kAlice, " b\n"), "line 2: token listed twice"},
      {"0123456789abcdef\xff x\n", "line 1: token holds a character outside printable ASCII"},
      {"# nothing\n\n", "holds no \"TOKEN TENANT\" line"},
  };
  for (const Case& c : cases) {
    const absl::Status s = ParseTokenFile(c.text, "tokens.txt").status();
    EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument) << c.text;
    EXPECT_THAT(s.message(), HasSubstr("\"tokens.txt\"")) << c.text;
    EXPECT_THAT(s.message(), HasSubstr(c.message)) << c.text;
    EXPECT_THAT(s.message(), Not(HasSubstr(kAlice))) << "never echo a token";
  }
}

TEST(BearerToken, TakesTheSchemeInAnyCaseAndTrimsBlanks) {
  EXPECT_EQ(BearerToken("Bearer abc"), "abc");
  EXPECT_EQ(BearerToken("bearer  abc "), "abc");
  EXPECT_EQ(BearerToken("BEARER abc"), "abc");
  EXPECT_FALSE(BearerToken("Basic abc").has_value());
  EXPECT_FALSE(BearerToken("Bearer ").has_value());
  EXPECT_FALSE(BearerToken("Bearer    ").has_value());
  EXPECT_FALSE(BearerToken("abc").has_value());
}

TEST(TokenAuth, ReloadSwapsTheTableAndKeepsItWhenTheNewFileIsBad) {
  const std::string path = testing_files::ScratchPath("tokens.txt");
  std::ofstream(path) << kAlice << " alice\n";
  const auto auth = TokenAuth::Load(path);
  ASSERT_TRUE(auth.ok()) << auth.status();
  EXPECT_EQ((*auth)->TenantOfToken(kAlice), "alice");
  EXPECT_FALSE((*auth)->TenantOfToken(kBob).has_value());

  std::ofstream(path) << kBob << " bob\n";
  const absl::StatusOr<int> reloaded = (*auth)->Reload();
  ASSERT_TRUE(reloaded.ok()) << reloaded.status();
  EXPECT_EQ(*reloaded, 1);
  EXPECT_FALSE((*auth)->TenantOfToken(kAlice).has_value()) << "a revoked token stops working";
  EXPECT_EQ((*auth)->TenantOfToken(kBob), "bob");

  std::ofstream(path) << "garbage\n";
  EXPECT_EQ((*auth)->Reload().status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ((*auth)->TenantOfToken(kBob), "bob") << "a bad file keeps the table in force";

  std::filesystem::remove(path);
  EXPECT_EQ((*auth)->Reload().status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ((*auth)->TenantOfToken(kBob), "bob");
}

TEST(TokenAuth, LoadNamesAMissingFile) {
  const auto auth = TokenAuth::Load("/nonexistent/tokens.txt");
  EXPECT_EQ(auth.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(auth.status().message(), HasSubstr("/nonexistent/tokens.txt"));
}

}  // namespace
}  // namespace meshseg::server
