// The pieces of a JSON log line (log.cc): strings escaped to valid JSON, and
// the level of an event.
#ifndef MESHSEG_SERVER_LOG_JSON_H_
#define MESHSEG_SERVER_LOG_JSON_H_

#include <string>
#include <string_view>

namespace meshseg::server {

// Returns `text` as a JSON string literal, quotes included: '"', '\' and
// control characters escaped, well-formed UTF-8 kept, and every byte that is
// not part of a well-formed UTF-8 sequence (Unicode table 3-7) written as
// \u00XX, so the line is valid JSON whatever bytes a value holds (a value
// may quote an uploaded file).
std::string JsonString(std::string_view text);

// "error", "warn" or "info": what an operator should look at. Events that
// lose work or need a person are errors; refused input, outages the server
// rides out and retried work are warnings.
std::string_view LevelOf(std::string_view event);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_LOG_JSON_H_
