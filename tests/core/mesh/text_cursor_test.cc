#include "mesh/text_cursor.h"

#include <cmath>

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

TEST(TextCursor, ReadsTokensLineByLineWithLineNumbers) {
  TextCursor cursor("a b\r\n\n  # comment\nc\t d # tail\n");
  ASSERT_TRUE(cursor.SkipEmptyLines());
  EXPECT_EQ(cursor.line(), 1);
  EXPECT_EQ(cursor.Token(), "a");
  EXPECT_EQ(cursor.Token(), "b");
  EXPECT_EQ(cursor.Token(), "");
  EXPECT_TRUE(cursor.AtLineEnd());
  cursor.NextLine();
  ASSERT_TRUE(cursor.SkipEmptyLines());
  EXPECT_EQ(cursor.line(), 4);
  EXPECT_EQ(cursor.Token(), "c");
  EXPECT_EQ(cursor.Token(), "d");
  EXPECT_TRUE(cursor.AtLineEnd());
  cursor.NextLine();
  EXPECT_FALSE(cursor.SkipEmptyLines());
  EXPECT_TRUE(cursor.AtEnd());
}

TEST(TextCursor, SplitsOnCommasWhenAsked) {
  TextCursor cursor("1,2, 3", /*comma_is_space=*/true);
  EXPECT_EQ(cursor.Token(), "1");
  EXPECT_EQ(cursor.Token(), "2");
  EXPECT_EQ(cursor.Token(), "3");
}

TEST(TextCursor, KeepsHashWhenCommentsAreOff) {
  TextCursor cursor("#a b");
  cursor.set_comments(false);
  EXPECT_EQ(cursor.Token(), "#a");
  EXPECT_EQ(cursor.RestOfLine(), " b");
}

TEST(ParseNumbers, AcceptsWholeTokensOnly) {
  EXPECT_EQ(ParseDouble("-1.5e3"), -1500.0);
  EXPECT_EQ(ParseDouble("+2"), 2.0);
  EXPECT_FALSE(ParseDouble("1.5x"));
  EXPECT_FALSE(ParseDouble(""));
  EXPECT_TRUE(std::isnan(*ParseDouble("nan")));
  EXPECT_EQ(ParseInt("-42"), -42);
  EXPECT_FALSE(ParseInt("4.2"));
  EXPECT_FALSE(ParseInt("99999999999999999999"));
}

TEST(Shorten, CutsLongTokens) {
  EXPECT_EQ(Shorten(std::string(100, 'x')).size(), 24u);
  EXPECT_EQ(Shorten("\xff\xfe\t3"), "\\xff\\xfe\\x093");
  EXPECT_EQ(StripLeadingSpace(" \n\tsolid"), "solid");
}

TEST(NextFinite, ReadsNumbersAndNamesTheFileLineAndToken) {
  const Source src{"read_mesh", "part.obj"};
  TextCursor cursor("1.5 -2e3\n4 nan x\n");
  ASSERT_TRUE(cursor.SkipEmptyLines());
  EXPECT_EQ(*NextFinite(src, cursor, "coordinate"), 1.5);
  EXPECT_EQ(*NextFinite(src, cursor, "coordinate"), -2000.0);
  const absl::StatusOr<double> end = NextFinite(src, cursor, "coordinate");
  EXPECT_EQ(end.status().message(), "read_mesh: \"part.obj\": line 1: expected a coordinate, got \"\"");
  cursor.NextLine();
  ASSERT_TRUE(cursor.SkipEmptyLines());
  EXPECT_EQ(*NextFinite(src, cursor, "number"), 4.0);
  const absl::StatusOr<double> nan = NextFinite(src, cursor, "number");
  EXPECT_EQ(nan.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(nan.status().message(), "read_mesh: \"part.obj\": line 2: non-finite number \"nan\"");
  EXPECT_EQ(NextFinite(src, cursor, "number").status().message(),
            "read_mesh: \"part.obj\": line 2: expected a number, got \"x\"");
}

}  // namespace
}  // namespace meshseg::mesh_internal
