// File: utf8.h
// -----------------------------------------------------------------------------
// Text that may carry bytes of an uploaded file (a reader's error message
// quoting a token, a file name) made safe for a proto `string` field, which
// must hold valid UTF-8: a parser drops the whole message otherwise, so one
// bad byte in Job.error_message would break ListJobs for every client.
#ifndef MESHSEG_PROTO_UTF8_H_
#define MESHSEG_PROTO_UTF8_H_

#include <cstddef>
#include <string>
#include <string_view>

namespace meshseg {

// Returns true if `text` is well-formed UTF-8 (Unicode 15 table 3-7: no
// overlong forms, no surrogates, nothing above U+10FFFF).
bool IsValidUtf8(std::string_view text);

// Returns the length (1-4) of the well-formed UTF-8 sequence at the start of
// `text`, or 0 if it does not start with one (Unicode 15 table 3-7).
std::size_t Utf8SequenceLength(std::string_view text);

// Returns `text` with every byte that is not part of a well-formed UTF-8
// sequence, and every ASCII control character, written as `\xNN` (two hex
// digits), so the result is valid UTF-8 on one line. Valid text other than
// control characters is returned unchanged.
std::string EscapeToUtf8(std::string_view text);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_UTF8_H_
