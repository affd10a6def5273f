// A real meshseg server on 127.0.0.1 with an ephemeral port and its own
// spool folder, for the service tests; and a runner that holds jobs until
// released or cancelled (to fill the queue and cancel mid-run).
#ifndef MESHSEG_TESTS_SERVER_TEST_SERVER_H_
#define MESHSEG_TESTS_SERVER_TEST_SERVER_H_

#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

#include "absl/synchronization/notification.h"
#include "client/meshseg_client.h"
#include "scratch_dir.h"
#include "server/server.h"

namespace meshseg::testing_server {

// Returns a fresh empty folder in the process's scratch folder.
inline std::string FreshDir(const std::string& name) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = testing_files::ScratchPath(
      std::string(info->test_suite_name()) + "_" + info->name() + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

class TestServer {
 public:
  explicit TestServer(server::ServerOptions options = {}) {
    options.listen = "127.0.0.1:0";
    spool_dir_ = FreshDir("spool");
    options.spool_dir = spool_dir_;
    if (options.workers == 0) options.workers = 2;
    // Tests that leave jobs held should not wait the production grace.
    if (options.shutdown_grace == server::ServerOptions{}.shutdown_grace) {
      options.shutdown_grace = absl::Seconds(1);
    }
    auto started = server::Server::Start(std::move(options));
    EXPECT_TRUE(started.ok()) << started.status();
    if (started.ok()) server_ = *std::move(started);
  }

  server::Server& server() { return *server_; }
  MeshsegClient Client() const { return MeshsegClient::Connect(server_->address()); }
  std::string address() const { return server_->address(); }
  int64_t SpoolFiles() const { return server_->SpoolFileCount(); }

 private:
  std::string spool_dir_;
  std::unique_ptr<server::Server> server_;
};

// Holds every job until Open() or until the job is cancelled, then runs the
// real pipeline.
struct Gate {
  absl::Notification open;
  std::atomic<int> entered{0};

  server::JobRunner Runner() {
    return [this](const std::string& path, const PipelineParams& params,
                  const RunContext& ctx) -> absl::StatusOr<PipelineResult> {
      ++entered;
      while (!open.WaitForNotificationWithTimeout(absl::Milliseconds(5))) {
        if (ctx.stop_requested()) return absl::CancelledError("test gate: stop requested");
      }
      return RunPipeline(path, params, ctx);
    };
  }
};

// Makes a unary call of `method` with the serialized `request` on a
// generic stub; returns its status and fills `response` with the bytes.
// `credentials`: plaintext unless given (TLS tests).
inline grpc::Status UnaryCall(const std::string& address, const std::string& method,
                              const std::string& request, std::string* response,
                              std::shared_ptr<grpc::ChannelCredentials> credentials = nullptr) {
  if (credentials == nullptr) credentials = grpc::InsecureChannelCredentials();
  auto channel = grpc::CreateChannel(address, credentials);
  grpc::GenericStub stub(channel);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(5)));
  grpc::CompletionQueue cq;
  grpc::Slice slice(request);
  grpc::ByteBuffer out(&slice, 1);
  auto call = stub.PrepareUnaryCall(&context, method, out, &cq);
  call->StartCall();
  grpc::ByteBuffer in;
  grpc::Status status;
  call->Finish(&in, &status, reinterpret_cast<void*>(1));
  void* tag = nullptr;
  bool ok = false;
  cq.Next(&tag, &ok);
  cq.Shutdown();
  while (cq.Next(&tag, &ok)) {
  }
  std::vector<grpc::Slice> slices;
  if (status.ok()) in.Dump(&slices);
  response->clear();
  for (const grpc::Slice& s : slices)
    response->append(reinterpret_cast<const char*>(s.begin()), s.size());
  return status;
}

// Returns the grpc.health.v1 status of the whole server: 1 = SERVING,
// 2 = NOT_SERVING, -1 = the call failed. The messages are tiny, so they are
// encoded by hand (HealthCheckRequest{} is empty; the response is field 1).
inline int HealthStatus(const std::string& address,
                        std::shared_ptr<grpc::ChannelCredentials> credentials = nullptr) {
  std::string bytes;
  const grpc::Status status =
      UnaryCall(address, "/grpc.health.v1.Health/Check", "", &bytes, std::move(credentials));
  if (!status.ok()) return -1;
  return bytes.size() == 2 && bytes[0] == 0x08 ? bytes[1] : (bytes.empty() ? 0 : -1);
}

// Polls `pred` for up to 10 s.
template <typename Pred>
bool Eventually(Pred pred) {
  const absl::Time deadline = absl::Now() + absl::Seconds(10);
  while (absl::Now() < deadline) {
    if (pred()) return true;
    absl::SleepFor(absl::Milliseconds(5));
  }
  return pred();
}

// Two jobs of the file at `path` on a one-worker server whose runner is
// `gate`'s: the first inside the gate (RUNNING), the second queued behind it.
struct RunningAndQueued {
  std::string running;
  std::string queued;
};
inline absl::StatusOr<RunningAndQueued> UploadRunningAndQueued(MeshsegClient& client,
                                                               const Gate& gate,
                                                               const std::string& path) {
  const absl::StatusOr<v1::UploadResponse> first = client.Upload(path);
  if (!first.ok()) return first.status();
  const absl::StatusOr<v1::UploadResponse> second = client.Upload(path);
  if (!second.ok()) return second.status();
  if (!Eventually([&] { return gate.entered == 1; })) {
    return absl::DeadlineExceededError("the first job never entered the gate");
  }
  return RunningAndQueued{.running = first->job_id(), .queued = second->job_id()};
}

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_TEST_SERVER_H_
