// Certificates for the TLS tests, made by the test with the openssl command
// line tool (Debian's openssl package): a CA, a server certificate for
// 127.0.0.1 / localhost and a client certificate signed by it, and a second
// CA with its own client certificate that the server must refuse. EC P-256
// keys, valid two days.
#ifndef MESHSEG_TESTS_SERVER_TEST_CERTS_H_
#define MESHSEG_TESTS_SERVER_TEST_CERTS_H_

#include <cstdlib>
#include <fstream>
#include <string>

#include "absl/strings/str_cat.h"

namespace meshseg::testing_server {

struct TestCerts {
  std::string ca;           // PEM of the CA that signed the server and client
  std::string server_cert;  // SAN IP:127.0.0.1, DNS:localhost
  std::string server_key;
  std::string client_cert;  // signed by `ca`
  std::string client_key;
  std::string other_ca;           // an unrelated CA
  std::string other_client_cert;  // signed by `other_ca`
  std::string other_client_key;
  bool ok = false;
};

namespace internal {

inline bool Run(const std::string& command) {
  return std::system(absl::StrCat(command, " >/dev/null 2>&1").c_str()) == 0;
}

// Makes `name`.key and a self-signed `name`.pem CA certificate in `dir`.
inline bool MakeCa(const std::string& dir, const std::string& name) {
  return Run(
      absl::StrCat("openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 "
                   "-nodes -days 2 -subj /CN=",
                   name, " -keyout ", dir, "/", name, ".key -out ", dir, "/", name, ".pem"));
}

// Makes `name`.key and `name`.pem signed by the CA `ca` in `dir`.
inline bool MakeLeaf(const std::string& dir, const std::string& name, const std::string& ca,
                     const std::string& extensions) {
  const std::string ext = absl::StrCat(dir, "/", name, ".ext");
  std::ofstream(ext) << extensions << "\n";
  return Run(absl::StrCat("openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes "
                          "-subj /CN=",
                          name, " -keyout ", dir, "/", name, ".key -out ", dir, "/", name,
                          ".csr")) &&
         Run(absl::StrCat("openssl x509 -req -days 2 -in ", dir, "/", name, ".csr -CA ", dir, "/",
                          ca, ".pem -CAkey ", dir, "/", ca, ".key -CAcreateserial -out ", dir, "/",
                          name, ".pem -extfile ", ext));
}

}  // namespace internal

// Returns the certificates, written into `dir` (which must exist).
inline TestCerts MakeTestCerts(const std::string& dir) {
  TestCerts c;
  const auto path = [&](const std::string& file) { return absl::StrCat(dir, "/", file); };
  c.ok = internal::MakeCa(dir, "ca") && internal::MakeCa(dir, "other-ca") &&
         internal::MakeLeaf(dir, "server", "ca",
                            "subjectAltName=IP:127.0.0.1,DNS:localhost\n"
                            "extendedKeyUsage=serverAuth") &&
         internal::MakeLeaf(dir, "client", "ca", "extendedKeyUsage=clientAuth") &&
         internal::MakeLeaf(dir, "other-client", "other-ca", "extendedKeyUsage=clientAuth");
  c.ca = path("ca.pem");
  c.server_cert = path("server.pem");
  c.server_key = path("server.key");
  c.client_cert = path("client.pem");
  c.client_key = path("client.key");
  c.other_ca = path("other-ca.pem");
  c.other_client_cert = path("other-client.pem");
  c.other_client_key = path("other-client.key");
  return c;
}

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_TEST_CERTS_H_
