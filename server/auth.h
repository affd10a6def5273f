// File: auth.h
// -----------------------------------------------------------------------------
// Bearer-token authentication: a token file maps tokens to tenant names; a
// grpc::AuthMetadataProcessor refuses every call without a known token
// (UNAUTHENTICATED, before any handler runs), except the health service, so
// probes need no secret. Handlers ask TenantOf(context) whose jobs a call
// may see. The table is re-read on Reload() (main.cc calls it on SIGHUP).
//
// Token file: one "TOKEN TENANT" pair per line, '#' starts a comment.
// Tokens are at least 16 printable ASCII characters without spaces or '#'; tenants
// are 1-64 characters of [A-Za-z0-9._-]; a token may appear once.
//
// gRPC shares one AuthContext between all calls of a connection (its
// properties accumulate), so the tenant is looked up from each call's own
// "authorization" metadata, never from AuthContext properties.
#ifndef MESHSEG_SERVER_AUTH_H_
#define MESHSEG_SERVER_AUTH_H_

#include <grpcpp/security/auth_metadata_processor.h>
#include <grpcpp/server_context.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"

namespace meshseg::server {

// Calls to methods under these prefixes need no token.
inline constexpr std::string_view kOpenMethodPrefix = "/grpc.health.v1.Health/";

// Returns the token -> tenant table in `text` (the token file's content);
// `file` names it in messages. Errors: INVALID_ARGUMENT naming the file, the
// line and what is wrong (never the token itself); an empty table.
absl::StatusOr<std::map<std::string, std::string>> ParseTokenFile(std::string_view text,
                                                                  std::string_view file);

class TokenAuth : public std::enable_shared_from_this<TokenAuth> {
 public:
  // Returns the tokens of the file at `path`. Errors: NOT_FOUND if it
  // cannot be read; those of ParseTokenFile.
  static absl::StatusOr<std::shared_ptr<TokenAuth>> Load(const std::string& path);

  // Re-reads the file; on error the old table stays in force. Returns the
  // number of tokens now in force. Thread-safe.
  absl::StatusOr<int> Reload();

  // Returns the tenant of `token`, or nullopt. Thread-safe.
  std::optional<std::string> TenantOfToken(std::string_view token) const;

  // Returns the tenant of the call, from its "authorization: Bearer TOKEN"
  // metadata. Errors: UNAUTHENTICATED (no bearer token, unknown token).
  absl::StatusOr<std::string> TenantOf(const grpc::ServerContextBase& context) const;

  // Returns the processor to install on the server's credentials.
  std::shared_ptr<grpc::AuthMetadataProcessor> Processor();

 private:
  TokenAuth(std::string path, std::map<std::string, std::string> by_digest)
      : path_(std::move(path)), by_digest_(std::move(by_digest)) {}

  const std::string path_;
  mutable absl::Mutex mu_;
  // SHA-256 of the token (hex) -> tenant: a lookup by digest compares no
  // secret byte by byte.
  std::map<std::string, std::string> by_digest_ ABSL_GUARDED_BY(mu_);
};

// Returns the bearer token in an "authorization" metadata value ("Bearer
// TOKEN", the scheme in any case), or nullopt.
std::optional<std::string_view> BearerToken(std::string_view authorization);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_AUTH_H_
