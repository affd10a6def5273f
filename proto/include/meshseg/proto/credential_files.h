// File: credential_files.h
// -----------------------------------------------------------------------------
// The small files both ends of the API read to secure a connection: PEM
// certificates and keys (server and client TLS) and the server's token file.
#ifndef MESHSEG_PROTO_CREDENTIAL_FILES_H_
#define MESHSEG_PROTO_CREDENTIAL_FILES_H_

#include <string>

#include "absl/status/statusor.h"

namespace meshseg {

// Returns the whole content of the file at `path`; `flag` (e.g. "--tls-ca")
// names it in messages. Errors: NOT_FOUND `<flag>: cannot read "<path>"` if
// it cannot be opened or is empty.
absl::StatusOr<std::string> ReadCredentialFile(const std::string& path, const char* flag);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_CREDENTIAL_FILES_H_
