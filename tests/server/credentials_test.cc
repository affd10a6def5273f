// TLS, mutual TLS and bearer tokens on a real gRPC server on 127.0.0.1,
// with certificates the test makes with openssl (test_certs.h). The server
// answers every Segmentation method with a Job whose job_id is the caller's
// tenant (TokenAuth::TenantOf), so the real client library is what connects.
#include "server/credentials.h"

#include <gmock/gmock.h>
#include <grpcpp/generic/async_generic_service.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

#include "client/meshseg_client.h"
#include "scratch_dir.h"
#include "tests/server/test_certs.h"
#include "tests/server/test_server.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::TestCerts;

constexpr char kAlice[] = "alice-token-0123456789";
constexpr char kBob[] = "bob-token-0123456789ab";

// Answers any method with a v1::Job naming the caller's tenant ("" without
// auth), or the UNAUTHENTICATED TenantOf gives.
class TenantEcho : public grpc::CallbackGenericService {
 public:
  explicit TenantEcho(std::shared_ptr<TokenAuth> auth) : auth_(std::move(auth)) {}

  grpc::ServerGenericBidiReactor* CreateReactor(
      grpc::GenericCallbackServerContext* context) override {
    class Reactor : public grpc::ServerGenericBidiReactor {
     public:
      Reactor(grpc::GenericCallbackServerContext* context, const TokenAuth* auth)
          : context_(context), auth_(auth) {
        StartRead(&request_);
      }
      void OnReadDone(bool ok) override {
        if (!ok) return Finish(grpc::Status(grpc::StatusCode::INTERNAL, "no request"));
        v1::Job job;
        if (auth_ != nullptr) {
          const absl::StatusOr<std::string> tenant = auth_->TenantOf(*context_);
          if (!tenant.ok()) {
            return Finish(grpc::Status(grpc::StatusCode::UNAUTHENTICATED,
                                       std::string(tenant.status().message())));
          }
          job.set_job_id(*tenant);
        }
        bool own = false;
        grpc::SerializationTraits<v1::Job>::Serialize(job, &response_, &own);
        StartWrite(&response_);
      }
      void OnWriteDone(bool /*ok*/) override { Finish(grpc::Status::OK); }
      void OnDone() override { delete this; }

     private:
      grpc::GenericCallbackServerContext* context_;
      const TokenAuth* auth_;
      grpc::ByteBuffer request_;
      grpc::ByteBuffer response_;
    };
    return new Reactor(context, auth_.get());
  }

 private:
  std::shared_ptr<TokenAuth> auth_;
};

// A server on 127.0.0.1:0 with BuildTransport's credentials.
class SecureServer {
 public:
  SecureServer(const SecurityOptions& options, std::shared_ptr<TokenAuth> auth) : echo_(auth) {
    const absl::StatusOr<Transport> transport = BuildTransport(options, "127.0.0.1:0", auth);
    EXPECT_TRUE(transport.ok()) << transport.status();
    if (!transport.ok()) return;
    grpc::EnableDefaultHealthCheckService(true);
    grpc::ServerBuilder builder;
    builder.AddListeningPort(transport->listen, transport->credentials, &port_);
    builder.RegisterCallbackGenericService(&echo_);
    server_ = builder.BuildAndStart();
    EXPECT_NE(port_, 0);
  }
  ~SecureServer() {
    if (server_) server_->Shutdown(std::chrono::system_clock::now());
  }
  std::string address() const { return absl::StrCat("127.0.0.1:", port_); }

 private:
  TenantEcho echo_;
  int port_ = 0;
  std::unique_ptr<grpc::Server> server_;
};

// Returns the tenant the server saw for a GetJob through the client library
// (the job_id it answered), or the call's error.
absl::StatusOr<std::string> CallAs(const std::string& address, const ConnectOptions& options) {
  absl::StatusOr<MeshsegClient> client = MeshsegClient::Connect(address, options);
  if (!client.ok()) return client.status();
  client->set_call_timeout(absl::Seconds(5));
  absl::StatusOr<v1::Job> job = client->GetJob("job-0");
  if (!job.ok()) return job.status();
  return job->job_id();
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class Credentials : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing_files::ScratchPath("certs"));
    std::filesystem::create_directories(*dir_);
    certs_ = new TestCerts(testing_server::MakeTestCerts(*dir_));
  }
  static void TearDownTestSuite() {
    delete certs_;
    delete dir_;
  }
  void SetUp() override { ASSERT_TRUE(certs_->ok) << "openssl could not make the certificates"; }

  std::shared_ptr<TokenAuth> Tokens() {
    const std::string path = FreshDir("auth") + "/tokens.txt";
    std::ofstream(path) << kAlice << " alice\n" << kBob << " bob\n";
    absl::StatusOr<std::shared_ptr<TokenAuth>> auth = TokenAuth::Load(path);
    EXPECT_TRUE(auth.ok()) << auth.status();
    return auth.ok() ? *auth : nullptr;
  }

  static std::string* dir_;
  static TestCerts* certs_;
};
std::string* Credentials::dir_ = nullptr;
TestCerts* Credentials::certs_ = nullptr;

TEST_F(Credentials, TlsHandshakeNeedsTheServersCa) {
  SecureServer server({.tls_cert = certs_->server_cert, .tls_key = certs_->server_key}, nullptr);
  EXPECT_EQ(CallAs(server.address(), {.tls_ca = certs_->ca}).status(), absl::OkStatus());
  // A client that trusts another CA, or speaks plaintext, gets no answer.
  EXPECT_EQ(CallAs(server.address(), {.tls_ca = certs_->other_ca}).status().code(),
            absl::StatusCode::kUnavailable);
  EXPECT_EQ(CallAs(server.address(), {}).status().code(), absl::StatusCode::kUnavailable);
}

TEST_F(Credentials, MutualTlsRefusesClientsWithoutACertificateOfItsCa) {
  SecureServer server(
      {.tls_cert = certs_->server_cert, .tls_key = certs_->server_key, .tls_client_ca = certs_->ca},
      nullptr);
  EXPECT_EQ(
      CallAs(server.address(),
             {.tls_ca = certs_->ca, .tls_cert = certs_->client_cert, .tls_key = certs_->client_key})
          .status(),
      absl::OkStatus());
  EXPECT_EQ(CallAs(server.address(), {.tls_ca = certs_->ca}).status().code(),
            absl::StatusCode::kUnavailable)
      << "no client certificate";
  EXPECT_EQ(CallAs(server.address(), {.tls_ca = certs_->ca,
                                      .tls_cert = certs_->other_client_cert,
                                      .tls_key = certs_->other_client_key})
                .status()
                .code(),
            absl::StatusCode::kUnavailable)
      << "a certificate of another CA";
}

TEST_F(Credentials, TokensMapToTenantsPerCallAndHealthNeedsNone) {
  SecureServer server({.tls_cert = certs_->server_cert, .tls_key = certs_->server_key}, Tokens());
  const ConnectOptions tls{.tls_ca = certs_->ca};
  ConnectOptions alice = tls, bob = tls, wrong = tls;
  alice.token = kAlice;
  bob.token = kBob;
  wrong.token = "not-a-token-0123456789";
  EXPECT_EQ(CallAs(server.address(), alice).value_or("?"), "alice");
  EXPECT_EQ(CallAs(server.address(), bob).value_or("?"), "bob");
  const absl::Status none = CallAs(server.address(), tls).status();
  EXPECT_EQ(none.code(), absl::StatusCode::kUnauthenticated);
  EXPECT_THAT(none.message(), HasSubstr("no bearer token"));
  const absl::Status bad = CallAs(server.address(), wrong).status();
  EXPECT_EQ(bad.code(), absl::StatusCode::kUnauthenticated);
  EXPECT_THAT(bad.message(), HasSubstr("unknown bearer token"));

  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = ReadAll(certs_->ca);
  EXPECT_EQ(testing_server::HealthStatus(server.address(), grpc::SslCredentials(ssl)), 1)
      << "probes need no token";
}

// gRPC shares one AuthContext per connection; tenants must still be per
// call when one channel carries two tenants' tokens.
TEST_F(Credentials, OneConnectionCarryingTwoTenantsKeepsThemApart) {
  SecureServer server({.tls_cert = certs_->server_cert, .tls_key = certs_->server_key}, Tokens());
  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = ReadAll(certs_->ca);
  const auto channel = grpc::CreateChannel(server.address(), grpc::SslCredentials(ssl));
  MeshsegClient alice(channel, kAlice);
  MeshsegClient bob(channel, kBob);
  for (int round = 0; round < 3; ++round) {
    EXPECT_EQ(alice.GetJob("job-0").value_or(v1::Job()).job_id(), "alice") << round;
    EXPECT_EQ(bob.GetJob("job-0").value_or(v1::Job()).job_id(), "bob") << round;
  }
}

TEST_F(Credentials, TokensWithoutTlsWorkOnLoopback) {
  SecureServer server({}, Tokens());
  EXPECT_EQ(CallAs(server.address(), {.token = kBob}).value_or("?"), "bob");
  EXPECT_EQ(CallAs(server.address(), {}).status().code(), absl::StatusCode::kUnauthenticated);
  EXPECT_EQ(testing_server::HealthStatus(server.address(), grpc::InsecureChannelCredentials()), 1);
}

TEST(BuildTransport, PlaintextListensOnLoopbackUnlessInsecure) {
  const absl::StatusOr<Transport> plain = BuildTransport({}, "0.0.0.0:50051", nullptr);
  ASSERT_TRUE(plain.ok()) << plain.status();
  EXPECT_EQ(plain->listen, "127.0.0.1:50051");
  EXPECT_EQ(plain->mode, "plaintext");
  EXPECT_THAT(plain->note, HasSubstr("--insecure"));

  const absl::StatusOr<Transport> open =
      BuildTransport({.insecure = true}, "0.0.0.0:50051", nullptr);
  ASSERT_TRUE(open.ok()) << open.status();
  EXPECT_EQ(open->listen, "0.0.0.0:50051");
  EXPECT_TRUE(open->note.empty());

  for (const char* loopback : {"127.0.0.1:1", "localhost:1", "[::1]:1"}) {
    const absl::StatusOr<Transport> t = BuildTransport({}, loopback, nullptr);
    ASSERT_TRUE(t.ok()) << t.status();
    EXPECT_EQ(t->listen, loopback);
    EXPECT_TRUE(t->note.empty()) << loopback;
  }
}

TEST(BuildTransport, RefusesIncompleteOrUnsafeCombinationsNamingTheFlag) {
  struct Case {
    SecurityOptions options;
    bool tokens;
    absl::StatusCode code;
    const char* message;
  };
  const Case cases[] = {
      {{.tls_cert = "c.pem"}, false, absl::StatusCode::kInvalidArgument, "--tls-key"},
      {{.tls_key = "k.pem"}, false, absl::StatusCode::kInvalidArgument, "--tls-cert"},
      {{.tls_client_ca = "ca.pem"}, false, absl::StatusCode::kInvalidArgument, "--tls-client-ca"},
      {{.insecure = true}, true, absl::StatusCode::kInvalidArgument, "in the clear"},
      {{.tls_cert = "/nonexistent/c.pem", .tls_key = "/nonexistent/k.pem"},
       false,
       absl::StatusCode::kNotFound,
       "/nonexistent/"},
  };
  const std::string path = testing_files::ScratchPath("tokens.txt");
  std::ofstream(path) << kAlice << " alice\n";
  const std::shared_ptr<TokenAuth> auth = *TokenAuth::Load(path);
  for (const Case& c : cases) {
    const absl::Status s =
        BuildTransport(c.options, "0.0.0.0:1", c.tokens ? auth : nullptr).status();
    EXPECT_EQ(s.code(), c.code) << c.message;
    EXPECT_THAT(s.message(), HasSubstr(c.message));
  }
}

}  // namespace
}  // namespace meshseg::server
