#include "mesh/text_cursor.h"

#include <charconv>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace meshseg::mesh_internal {

void TextCursor::SkipBlanks() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' ||
        (comma_is_space_ && c == ',')) {
      ++pos_;
    } else {
      break;
    }
  }
}

bool TextCursor::AtLineEnd() {
  SkipBlanks();
  return pos_ >= text_.size() || text_[pos_] == '\n' || (comments_ && text_[pos_] == '#');
}

std::string_view TextCursor::Token() {
  if (AtLineEnd()) return {};
  const size_t start = pos_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' ||
        (comma_is_space_ && c == ',')) {
      break;
    }
    ++pos_;
  }
  return text_.substr(start, pos_ - start);
}

void TextCursor::NextLine() {
  const size_t nl = text_.find('\n', pos_);
  if (nl == std::string_view::npos) {
    pos_ = text_.size();
  } else {
    pos_ = nl + 1;
    ++line_;
  }
}

bool TextCursor::SkipEmptyLines() {
  while (!AtEnd()) {
    if (!AtLineEnd()) return true;
    NextLine();
  }
  return false;
}

std::string_view TextCursor::RestOfLine() const {
  size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  std::string_view rest = text_.substr(pos_, end - pos_);
  while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ')) rest.remove_suffix(1);
  return rest;
}

std::optional<double> ParseDouble(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size() || token.empty()) {
    return std::nullopt;
  }
  return value;
}

std::optional<int64_t> ParseInt(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  int64_t value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size() || token.empty()) {
    return std::nullopt;
  }
  return value;
}

absl::Status AtLine(const Source& src, const TextCursor& cursor, const std::string& what) {
  return BadInput(src, absl::StrCat("line ", cursor.line(), ": ", what));
}

absl::StatusOr<double> NextFinite(const Source& src, TextCursor& cursor, const char* noun) {
  const std::string_view token = cursor.Token();
  const std::optional<double> value = ParseDouble(token);
  if (!value) {
    return BadInput(src, absl::StrCat("line ", cursor.line(), ": expected a ", noun, ", got \"",
                                      Shorten(token), "\""));
  }
  if (!std::isfinite(*value)) {
    return BadInput(src, absl::StrCat("line ", cursor.line(), ": non-finite ", noun, " \"",
                                      Shorten(token), "\""));
  }
  return *value;
}

std::string_view StripLeadingSpace(std::string_view text) {
  const size_t start = text.find_first_not_of(" \t\r\n\v\f");
  return start == std::string_view::npos ? std::string_view() : text.substr(start);
}

std::string Shorten(std::string_view token) {
  std::string out;
  for (const char c : token.substr(0, 24)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F) {
      out.push_back(c);
    } else {
      absl::StrAppend(&out, "\\x", absl::Hex(byte, absl::kZeroPad2));
    }
  }
  return out;
}

}  // namespace meshseg::mesh_internal
