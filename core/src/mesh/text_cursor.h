// A cursor over the text of an ASCII mesh or point-cloud file: tokens within
// a line, line numbers for messages, and number parsing.
#ifndef MESHSEG_MESH_TEXT_CURSOR_H_
#define MESHSEG_MESH_TEXT_CURSOR_H_

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

class TextCursor {
 public:
  // `comma_is_space`: commas separate values like blanks (XYZ files).
  explicit TextCursor(std::string_view text, bool comma_is_space = false)
      : text_(text), comma_is_space_(comma_is_space) {}

  // True when the whole text is consumed.
  bool AtEnd() const { return pos_ >= text_.size(); }
  // 1-based number of the line the cursor is on.
  int64_t line() const { return line_; }
  // Byte offset of the cursor.
  size_t offset() const { return pos_; }

  // Returns the next token on the current line, or "" at the end of the line
  // (a '#' starts a comment that ends the line when `comments_` is on).
  std::string_view Token();
  // True if the current line has no more tokens.
  bool AtLineEnd();
  // Moves to the start of the next line.
  void NextLine();
  // Skips lines without tokens; returns false at the end of the text.
  bool SkipEmptyLines();
  // The rest of the current line (for messages and headers), without the
  // newline; does not move.
  std::string_view RestOfLine() const;

  void set_comments(bool on) { comments_ = on; }

 private:
  void SkipBlanks();

  std::string_view text_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  bool comma_is_space_;
  bool comments_ = true;
};

// Parses a whole token as a double / an integer; nullopt if it is not one.
std::optional<double> ParseDouble(std::string_view token);
std::optional<int64_t> ParseInt(std::string_view token);

// Returns INVALID_ARGUMENT `<op>: "<file>": line N: <what>` for the line of `cursor`.
absl::Status AtLine(const Source& src, const TextCursor& cursor, const std::string& what);

// Reads the next token on the cursor's line as a finite number. Errors
// (INVALID_ARGUMENT naming the file and line): `line N: expected a <noun>,
// got "tok"` and `line N: non-finite <noun> "tok"`; `noun` is "coordinate"
// or "number".
absl::StatusOr<double> NextFinite(const Source& src, TextCursor& cursor, const char* noun);

// Returns `text` without leading blanks and newlines.
std::string_view StripLeadingSpace(std::string_view text);

// Returns a token for a message: its first 24 bytes, each byte outside
// printable ASCII written as \xNN, so a message quoting a binary file's
// bytes stays one readable line.
std::string Shorten(std::string_view token);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_TEXT_CURSOR_H_
