// File: log.h
// -----------------------------------------------------------------------------
// Structured log lines on stderr: `ts=<RFC3339> event=<name> key=value ...`,
// one line per call, values quoted when they hold spaces or quotes.
#ifndef MESHSEG_SERVER_LOG_H_
#define MESHSEG_SERVER_LOG_H_

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace meshseg::server {

using LogField = std::pair<std::string_view, std::string>;

// Writes one line: the time, `event`, then `fields` in order. Thread-safe.
void Log(std::string_view event, std::initializer_list<LogField> fields = {});

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_LOG_H_
