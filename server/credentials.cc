#include "server/credentials.h"

#include <grpcpp/security/server_credentials.h>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/credential_files.h"
#include "meshseg/status_macros.h"

namespace meshseg::server {
namespace {

// Returns the host part of HOST:PORT ("[::1]" keeps its brackets).
std::string HostOf(const std::string& listen) { return listen.substr(0, listen.rfind(':')); }

std::string PortOf(const std::string& listen) { return listen.substr(listen.rfind(':') + 1); }

absl::StatusOr<std::shared_ptr<grpc::ServerCredentials>> TlsCredentials(
    const SecurityOptions& options) {
  grpc::SslServerCredentialsOptions ssl;
  grpc::SslServerCredentialsOptions::PemKeyCertPair pair;
  MESHSEG_ASSIGN_OR_RETURN(pair.private_key, ReadCredentialFile(options.tls_key, "--tls-key"));
  MESHSEG_ASSIGN_OR_RETURN(pair.cert_chain, ReadCredentialFile(options.tls_cert, "--tls-cert"));
  ssl.pem_key_cert_pairs.push_back(std::move(pair));
  if (!options.tls_client_ca.empty()) {
    MESHSEG_ASSIGN_OR_RETURN(ssl.pem_root_certs,
                             ReadCredentialFile(options.tls_client_ca, "--tls-client-ca"));
    ssl.client_certificate_request = GRPC_SSL_REQUEST_AND_REQUIRE_CLIENT_CERTIFICATE_AND_VERIFY;
  }
  return grpc::SslServerCredentials(ssl);
}

}  // namespace

bool IsLoopbackHost(const std::string& host) {
  return host == "localhost" || host == "[::1]" || host.rfind("127.", 0) == 0;
}

absl::StatusOr<Transport> BuildTransport(const SecurityOptions& options, const std::string& listen,
                                         const std::shared_ptr<TokenAuth>& auth) {
  if (options.tls_cert.empty() != options.tls_key.empty()) {
    return absl::InvalidArgumentError("--tls-cert and --tls-key must be given together");
  }
  const bool tls = !options.tls_cert.empty();
  if (!tls && !options.tls_client_ca.empty()) {
    return absl::InvalidArgumentError("--tls-client-ca needs --tls-cert and --tls-key");
  }
  Transport t;
  t.listen = listen;
  if (tls) {
    MESHSEG_ASSIGN_OR_RETURN(t.credentials, TlsCredentials(options));
    t.mode = options.tls_client_ca.empty() ? "tls" : "mtls";
  } else if (auth != nullptr) {
    if (options.insecure) {
      return absl::InvalidArgumentError(
          "--auth-tokens with --insecure and no TLS would send tokens over the network in the "
          "clear: give --tls-cert and --tls-key");
    }
    // gRPC's local credentials accept loopback peers only and carry the
    // token processor; the wire is plaintext HTTP/2.
    t.credentials = grpc::experimental::LocalServerCredentials(LOCAL_TCP);
    t.mode = "local";
  } else {
    t.credentials = grpc::InsecureServerCredentials();
    t.mode = "plaintext";
  }
  if (!tls && !options.insecure && !IsLoopbackHost(HostOf(listen))) {
    t.listen = absl::StrCat("127.0.0.1:", PortOf(listen));
    t.note = absl::StrCat("no TLS: listening on ", t.listen, " instead of ", listen,
                          " (give --tls-cert/--tls-key, or --insecure to accept plaintext "
                          "from the network)");
  }
  if (auth != nullptr) t.credentials->SetAuthMetadataProcessor(auth->Processor());
  return t;
}

}  // namespace meshseg::server
