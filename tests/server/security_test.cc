// The real meshseg server (Server::Start, as main.cc runs it) on 127.0.0.1
// with TLS, mutual TLS and bearer tokens: certificates made by the test with
// openssl (test_certs.h), jobs uploaded and run through the client library.
// Also: reflection is off unless asked for, tokens are re-read on
// ReloadTokens() (main.cc's SIGHUP), and a server without TLS binds
// loopback only unless --insecure.
#include <gmock/gmock.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

#include "client/meshseg_client.h"
#include "server/server.h"
#include "tests/server/test_certs.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::HealthStatus;
using testing_server::TestCerts;

constexpr char kAlice[] = "alice-token-0123456789";
constexpr char kBob[] = "bob-token-0123456789ab";
constexpr char kCarol[] = "carol-token-0123456789";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Returns the status code of a unary call to `method` with an empty request.
grpc::StatusCode CallCode(const std::string& address, const std::string& method) {
  std::string response;
  return testing_server::UnaryCall(address, method, "", &response).error_code();
}

class Security : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string dir = testing_files::ScratchPath("security_certs");
    std::filesystem::create_directories(dir);
    certs_ = new TestCerts(testing_server::MakeTestCerts(dir));
  }
  static void TearDownTestSuite() { delete certs_; }

  void SetUp() override {
    ASSERT_TRUE(certs_->ok) << "openssl could not make the certificates";
    tokens_ = FreshDir("auth") + "/tokens.txt";
    std::ofstream(tokens_) << "# tenants of this test\n"
                           << kAlice << " alice\n"
                           << kBob << " bob\n";
    mesh_ = FreshDir("mesh") + "/box.stl";
    testing_files::WriteStlBinary(testing_files::SplitBox(2, {1, 1, 1}), mesh_);
  }

  // A server with TLS and tokens; mutual TLS if `mtls`.
  std::unique_ptr<testing_server::TestServer> Start(bool mtls) {
    ServerOptions options;
    options.security = {.tls_cert = certs_->server_cert,
                        .tls_key = certs_->server_key,
                        .tls_client_ca = mtls ? certs_->ca : "",
                        .auth_tokens = tokens_};
    return std::make_unique<testing_server::TestServer>(std::move(options));
  }

  absl::StatusOr<MeshsegClient> Client(const std::string& address, const std::string& token,
                                       bool client_cert = false) {
    ConnectOptions options{.tls_ca = certs_->ca, .token = token};
    if (client_cert) {
      options.tls_cert = certs_->client_cert;
      options.tls_key = certs_->client_key;
    }
    absl::StatusOr<MeshsegClient> client = MeshsegClient::Connect(address, options);
    if (client.ok()) client->set_call_timeout(absl::Seconds(20));
    return client;
  }

  static TestCerts* certs_;
  std::string tokens_;
  std::string mesh_;
};
TestCerts* Security::certs_ = nullptr;

TEST_F(Security, TlsWithTokensRunsAJobAndRefusesCallsWithoutAKnownToken) {
  const auto server = Start(/*mtls=*/false);
  absl::StatusOr<MeshsegClient> alice = Client(server->address(), kAlice);
  ASSERT_TRUE(alice.ok()) << alice.status();
  const absl::StatusOr<v1::SegmentationResult> result = alice->Segment(mesh_);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->regions_size(), 0);

  for (const char* token : {"", "not-a-token-0123456789"}) {
    absl::StatusOr<MeshsegClient> stranger = Client(server->address(), token);
    ASSERT_TRUE(stranger.ok());
    EXPECT_EQ(stranger->ListJobs().status().code(), absl::StatusCode::kUnauthenticated) << token;
    EXPECT_EQ(stranger->Upload(mesh_).status().code(), absl::StatusCode::kUnauthenticated);
  }
  // Plaintext gets no answer from a TLS port; health needs TLS but no token.
  EXPECT_EQ(HealthStatus(server->address()), -1);
  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = ReadFile(certs_->ca);
  EXPECT_EQ(HealthStatus(server->address(), grpc::SslCredentials(ssl)), 1);
}

TEST_F(Security, MutualTlsNeedsAClientCertificateSignedByTheClientCa) {
  const auto server = Start(/*mtls=*/true);
  absl::StatusOr<MeshsegClient> with_cert = Client(server->address(), kAlice, true);
  ASSERT_TRUE(with_cert.ok()) << with_cert.status();
  EXPECT_TRUE(with_cert->ListJobs().ok());
  absl::StatusOr<MeshsegClient> without = Client(server->address(), kAlice, false);
  ASSERT_TRUE(without.ok());
  without->set_call_timeout(absl::Seconds(3));
  EXPECT_EQ(without->ListJobs().status().code(), absl::StatusCode::kUnavailable);

  absl::StatusOr<MeshsegClient> other =
      MeshsegClient::Connect(server->address(), {.tls_ca = certs_->ca,
                                                 .tls_cert = certs_->other_client_cert,
                                                 .tls_key = certs_->other_client_key,
                                                 .token = kAlice});
  ASSERT_TRUE(other.ok());
  other->set_call_timeout(absl::Seconds(3));
  EXPECT_EQ(other->ListJobs().status().code(), absl::StatusCode::kUnavailable);
}

TEST_F(Security, ReloadedTokensTakeEffectAndABadFileKeepsTheOldOnes) {
  const auto server = Start(/*mtls=*/false);
  absl::StatusOr<MeshsegClient> carol = Client(server->address(), kCarol);
  ASSERT_TRUE(carol.ok());
  EXPECT_EQ(carol->ListJobs().status().code(), absl::StatusCode::kUnauthenticated);

  // Bob leaves, Carol arrives.
  std::ofstream(tokens_, std::ios::trunc) << kAlice << " alice\n" << kCarol << " carol\n";
  const absl::StatusOr<int> count = server->server().ReloadTokens();
  ASSERT_TRUE(count.ok()) << count.status();
  EXPECT_EQ(*count, 2);
  EXPECT_TRUE(carol->ListJobs().ok());
  absl::StatusOr<MeshsegClient> bob = Client(server->address(), kBob);
  ASSERT_TRUE(bob.ok());
  EXPECT_EQ(bob->ListJobs().status().code(), absl::StatusCode::kUnauthenticated);

  // A broken file is refused (line named) and the tokens in force stay.
  std::ofstream(tokens_, std::ios::trunc) << "short alice\n";
  const absl::StatusOr<int> bad = server->server().ReloadTokens();
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad.status().message(), HasSubstr("line 1"));
  EXPECT_TRUE(carol->ListJobs().ok());
}

TEST_F(Security, ReflectionIsOffUnlessAsked) {
  constexpr char kMethod[] = "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo";
  testing_server::TestServer plain;
  EXPECT_EQ(CallCode(plain.address(), kMethod), grpc::StatusCode::UNIMPLEMENTED);
  EXPECT_FALSE(plain.server().ReloadTokens().ok());  // no --auth-tokens
  ServerOptions options;
  options.reflection = true;
  testing_server::TestServer reflecting(std::move(options));
  EXPECT_NE(CallCode(reflecting.address(), kMethod), grpc::StatusCode::UNIMPLEMENTED);
}

TEST_F(Security, WithoutTlsTheServerListensOnLoopbackUnlessInsecure) {
  ServerOptions options;
  options.listen = "0.0.0.0:0";
  options.spool_dir = FreshDir("spool");
  options.workers = 1;
  absl::StatusOr<std::unique_ptr<Server>> moved = Server::Start(options);
  ASSERT_TRUE(moved.ok()) << moved.status();
  EXPECT_THAT((*moved)->address(), ::testing::StartsWith("127.0.0.1:"));
  (*moved).reset();

  options.security.insecure = true;
  absl::StatusOr<std::unique_ptr<Server>> open = Server::Start(options);
  ASSERT_TRUE(open.ok()) << open.status();
  EXPECT_THAT((*open)->address(), ::testing::StartsWith("0.0.0.0:"));
}

TEST_F(Security, BadSecurityFlagsAreRefusedAtStart) {
  ServerOptions options;
  options.listen = "127.0.0.1:0";
  options.spool_dir = FreshDir("spool");
  options.security.tls_cert = certs_->server_cert;  // no key
  EXPECT_EQ(Server::Start(options).status().code(), absl::StatusCode::kInvalidArgument);
  options.security = {.auth_tokens = FreshDir("none") + "/missing.txt"};
  EXPECT_EQ(Server::Start(options).status().code(), absl::StatusCode::kNotFound);
}

}  // namespace
}  // namespace meshseg::server
