// Compiled, never run, by ctest (tests/server/CMakeLists.txt): a log call
// with a key from kLogKeys compiles; with MESHSEG_LOG_FORBIDDEN_KEY defined,
// a call logging the authorization metadata must fail to compile, naming
// NotAnAllowedLogKey. That is the guarantee that no call site can log a
// token by key.
#include <string>

#include "server/log.h"

void LogsAnAllowedKey(const std::string& job) { meshseg::server::Log("job_started", {{"job", job}}); }

#ifdef MESHSEG_LOG_FORBIDDEN_KEY
void LogsTheAuthorizationHeader(const std::string& authorization) {
  meshseg::server::Log("upload_rejected", {{"authorization", authorization}});
}
#endif
