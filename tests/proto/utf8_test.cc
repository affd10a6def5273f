#include "meshseg/proto/utf8.h"

#include <gtest/gtest.h>

#include <string>

namespace meshseg {
namespace {

TEST(IsValidUtf8, AcceptsWellFormedText) {
  EXPECT_TRUE(IsValidUtf8(""));
  EXPECT_TRUE(IsValidUtf8("plate.stl"));
  EXPECT_TRUE(IsValidUtf8("\xC3\xA9"));                  // U+00E9
  EXPECT_TRUE(IsValidUtf8("\xE9\x83\xA8\xE5\x93\x81"));  // two CJK characters
  EXPECT_TRUE(IsValidUtf8("\xF0\x9F\x98\x80"));          // U+1F600
  EXPECT_TRUE(IsValidUtf8("\xF4\x8F\xBF\xBF"));          // U+10FFFF, the last code point
}

TEST(IsValidUtf8, RefusesEveryIllFormedKind) {
  EXPECT_FALSE(IsValidUtf8("\xff\xfe"));          // never UTF-8 bytes
  EXPECT_FALSE(IsValidUtf8("\x80"));              // lone continuation byte
  EXPECT_FALSE(IsValidUtf8("\xC3"));              // truncated sequence
  EXPECT_FALSE(IsValidUtf8("\xC0\xAF"));          // overlong '/'
  EXPECT_FALSE(IsValidUtf8("\xE0\x80\xAF"));      // overlong 3-byte form
  EXPECT_FALSE(IsValidUtf8("\xED\xA0\x80"));      // surrogate U+D800
  EXPECT_FALSE(IsValidUtf8("\xF4\x90\x80\x80"));  // above U+10FFFF
  EXPECT_FALSE(IsValidUtf8("\xF0\x9F\x98"));      // truncated 4-byte form
}

TEST(EscapeToUtf8, LeavesPrintableTextAlone) {
  const std::string text = "read_mesh: \"caf\xC3\xA9.off\": line 2";
  EXPECT_EQ(EscapeToUtf8(text), text);
}

TEST(EscapeToUtf8, EscapesBadBytesAndControlsOneByOne) {
  EXPECT_EQ(EscapeToUtf8("got \"\xff\xfe\""), "got \"\\xff\\xfe\"");
  EXPECT_EQ(EscapeToUtf8("a\nb\tc\x7f"), "a\\x0ab\\x09c\\x7f");
  // A truncated sequence before a valid character escapes only its bytes.
  EXPECT_EQ(EscapeToUtf8("\xE9\x83\xC3\xA9"), "\\xe9\\x83\xC3\xA9");
  EXPECT_EQ(EscapeToUtf8(std::string("nul\0end", 7)), "nul\\x00end");
}

TEST(EscapeToUtf8, OutputIsAlwaysValid) {
  // Every byte value, and every pair, escapes to valid UTF-8.
  std::string all;
  for (int b = 0; b < 256; ++b) all.push_back(static_cast<char>(b));
  EXPECT_TRUE(IsValidUtf8(EscapeToUtf8(all)));
  for (int a = 0x80; a < 256; a += 7) {
    for (int b = 0; b < 256; b += 3) {
      const std::string pair = {static_cast<char>(a), static_cast<char>(b)};
      EXPECT_TRUE(IsValidUtf8(EscapeToUtf8(pair))) << a << " " << b;
    }
  }
}

}  // namespace
}  // namespace meshseg
