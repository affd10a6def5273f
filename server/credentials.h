// File: credentials.h
// -----------------------------------------------------------------------------
// How meshseg-server listens: TLS (--tls-cert, --tls-key), mutual TLS
// (--tls-client-ca: clients must present a certificate it signed), bearer
// tokens (auth.h) on top, or plaintext. Plaintext without tokens is for
// loopback only unless --insecure says otherwise: the listen address is
// moved to 127.0.0.1 and the log says why.
//
//   TLS  tokens  insecure | credentials                    | address
//   yes  any     any      | TLS (+ mTLS), token processor  | as given
//   no   yes     no       | gRPC local (loopback peers)    | loopback
//   no   no      no       | plaintext                      | loopback
//   no   no      yes      | plaintext                      | as given
//   no   yes     yes      | refused: tokens would cross the network in the clear
#ifndef MESHSEG_SERVER_CREDENTIALS_H_
#define MESHSEG_SERVER_CREDENTIALS_H_

#include <grpcpp/security/server_credentials.h>

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "server/auth.h"

namespace meshseg::server {

struct SecurityOptions {
  // PEM files: the server's certificate chain and private key.
  std::string tls_cert = "";
  std::string tls_key = "";
  // PEM file of the CA that signs client certificates; set = mutual TLS.
  std::string tls_client_ca = "";
  // Token file (auth.h); empty = no authentication.
  std::string auth_tokens = "";
  // Allow plaintext without tokens on any address.
  bool insecure = false;
};

struct Transport {
  std::shared_ptr<grpc::ServerCredentials> credentials;
  // The address to bind: `listen`, or its port on 127.0.0.1.
  std::string listen;
  // "tls", "mtls", "local" (plaintext, loopback peers only) or "plaintext".
  std::string mode;
  // Set when the address was moved to loopback: why, for the log.
  std::string note;
};

// Returns true if `host` ("127.0.0.5", "localhost", "[::1]") is loopback.
bool IsLoopbackHost(const std::string& host);

// Returns the credentials and address for `listen` (HOST:PORT) under
// `options`; `auth` (may be null) is installed on secure credentials.
// Errors (INVALID_ARGUMENT naming the flag): a certificate without its key
// or the reverse, --tls-client-ca without --tls-cert, tokens with
// --insecure and no TLS; NOT_FOUND: a PEM file that cannot be read.
absl::StatusOr<Transport> BuildTransport(const SecurityOptions& options, const std::string& listen,
                                         const std::shared_ptr<TokenAuth>& auth);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_CREDENTIALS_H_
