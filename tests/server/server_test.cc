// The server as a whole: health, reflection, graceful shutdown, result expiry.
#include <google/protobuf/descriptor.h>
#include <google/protobuf/descriptor.pb.h>
#include <google/protobuf/descriptor_database.h>
#include <google/protobuf/message.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::HealthStatus;
using testing_server::RunningAndQueued;
using testing_server::TestServer;
using testing_server::UploadRunningAndQueued;

namespace pb = ::google::protobuf;

// grpc 1.51 serves reflection as v1alpha. Its messages are compiled into
// libgrpc++_reflection (no header is installed), so they are used through
// the generated pool.
constexpr char kReflection[] = "grpc.reflection.v1alpha.ServerReflection";

std::unique_ptr<pb::Message> NewMessage(const std::string& type) {
  const pb::Descriptor* d =
      pb::DescriptorPool::generated_pool()->FindMessageTypeByName(absl::StrCat(kReflection, type));
  EXPECT_NE(d, nullptr) << type;
  if (d == nullptr) return nullptr;
  return std::unique_ptr<pb::Message>(
      pb::MessageFactory::generated_factory()->GetPrototype(d)->New());
}

// Sends one ServerReflectionRequest with `field` = `value` on the
// ServerReflectionInfo stream and returns the response, or null on a failed
// call. Steps one at a time on a completion queue.
std::unique_ptr<pb::Message> Reflect(const std::string& address, const std::string& field,
                                     const std::string& value) {
  std::unique_ptr<pb::Message> request = NewMessage("Request");
  if (request == nullptr) return nullptr;
  request->GetReflection()->SetString(request.get(),
                                      request->GetDescriptor()->FindFieldByName(field), value);
  const std::string bytes = request->SerializeAsString();
  grpc::Slice slice(bytes);
  grpc::ByteBuffer out(&slice, 1);
  grpc::ByteBuffer in;
  grpc::Status status;

  grpc::GenericStub stub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(5)));
  grpc::CompletionQueue cq;
  auto call =
      stub.PrepareCall(&context, absl::StrCat("/", kReflection, "/ServerReflectionInfo"), &cq);
  auto step = [&cq] {
    void* tag = nullptr;
    bool ok = false;
    return cq.Next(&tag, &ok) && ok;
  };
  call->StartCall(nullptr);
  bool ok = step();
  if (ok) {
    call->Write(out, nullptr);
    ok = step();
  }
  if (ok) {
    call->WritesDone(nullptr);
    ok = step();
  }
  if (ok) {
    call->Read(&in, nullptr);
    ok = step();
  }
  call->Finish(&status, nullptr);
  step();
  cq.Shutdown();
  void* tag = nullptr;
  bool drained = false;
  while (cq.Next(&tag, &drained)) {
  }
  EXPECT_TRUE(ok && status.ok()) << status.error_code() << " " << status.error_message();
  if (!ok || !status.ok()) return nullptr;

  std::vector<grpc::Slice> slices;
  in.Dump(&slices);
  std::string received;
  for (const grpc::Slice& s : slices)
    received.append(reinterpret_cast<const char*>(s.begin()), s.size());
  std::unique_ptr<pb::Message> response = NewMessage("Response");
  EXPECT_TRUE(response->ParseFromString(received));
  return response;
}

// Returns the sub-message `field` of `message`.
const pb::Message& Field(const pb::Message& message, const std::string& field) {
  return message.GetReflection()->GetMessage(message,
                                             message.GetDescriptor()->FindFieldByName(field));
}

TEST(Server, ListensOnAnEphemeralPortAndIsServing) {
  TestServer server;
  EXPECT_GT(server.server().port(), 0);
  EXPECT_EQ(HealthStatus(server.address()), 1);
}

// What grpcurl does: list the services, then fetch the file declaring
// meshseg.v1.Segmentation (with its imports) and resolve it with no .proto
// files at hand.
TEST(Server, ReflectionListsAndDescribesTheSegmentationService) {
  TestServer server({.reflection = true});
  const std::unique_ptr<pb::Message> list = Reflect(server.address(), "list_services", "");
  ASSERT_NE(list, nullptr);
  const pb::Message& services = Field(*list, "list_services_response");
  const pb::FieldDescriptor* service = services.GetDescriptor()->FindFieldByName("service");
  std::vector<std::string> names;
  for (int i = 0; i < services.GetReflection()->FieldSize(services, service); ++i) {
    const pb::Message& s = services.GetReflection()->GetRepeatedMessage(services, service, i);
    names.push_back(s.GetReflection()->GetString(s, s.GetDescriptor()->FindFieldByName("name")));
  }
  EXPECT_THAT(names, ::testing::IsSupersetOf(
                         {"meshseg.v1.Segmentation", "grpc.health.v1.Health", kReflection}));

  const std::unique_ptr<pb::Message> files =
      Reflect(server.address(), "file_containing_symbol", "meshseg.v1.Segmentation");
  ASSERT_NE(files, nullptr);
  const pb::Message& response = Field(*files, "file_descriptor_response");
  const pb::FieldDescriptor* protos =
      response.GetDescriptor()->FindFieldByName("file_descriptor_proto");
  pb::SimpleDescriptorDatabase database;
  const int count = response.GetReflection()->FieldSize(response, protos);
  ASSERT_GE(count, 1);
  for (int i = 0; i < count; ++i) {
    pb::FileDescriptorProto file;
    ASSERT_TRUE(
        file.ParseFromString(response.GetReflection()->GetRepeatedString(response, protos, i)));
    ASSERT_TRUE(database.Add(file)) << file.name();
  }
  pb::DescriptorPool pool(&database);
  const pb::ServiceDescriptor* segmentation = pool.FindServiceByName("meshseg.v1.Segmentation");
  ASSERT_NE(segmentation, nullptr) << "the served files resolve, imports included";
  std::vector<std::string> methods;
  for (int i = 0; i < segmentation->method_count(); ++i) {
    methods.push_back(segmentation->method(i)->name());
  }
  EXPECT_THAT(methods, ::testing::IsSupersetOf(
                           {"Upload", "WatchJob", "GetResult", "GetJob", "ListJobs", "CancelJob"}));
  const pb::MethodDescriptor* upload = segmentation->FindMethodByName("Upload");
  ASSERT_NE(upload, nullptr);
  EXPECT_TRUE(upload->client_streaming());
  EXPECT_NE(pool.FindMessageTypeByName("meshseg.v1.SegmentationResult"), nullptr);
}

TEST(Server, HealthStaysServingAfterBadInput) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/broken.off";
  testing_files::WriteText(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_FALSE(client.Segment(path).ok());
  EXPECT_EQ(HealthStatus(server.address()), 1);
}

// Queued jobs stay QUEUED (in the spool, for the next start: recovery_test).
TEST(Server, ShutdownLetsRunningJobsFinishAndKeepsQueuedOnes) {
  Gate gate;
  TestServer server({.workers = 1, .shutdown_grace = absl::Seconds(10), .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const absl::StatusOr<RunningAndQueued> jobs = UploadRunningAndQueued(client, gate, path);
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  const std::string& running = jobs->running;
  const std::string& queued = jobs->queued;
  std::thread stopper([&] { server.server().Shutdown(); });
  ASSERT_TRUE(Eventually([&] { return HealthStatus(server.address()) == 2; }));
  EXPECT_EQ(client.Upload(path).status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(client.GetJob(queued)->state(), v1::JOB_STATE_QUEUED);
  // Watch from before the job ends: once it has ended the server may finish
  // shutting down and refuse a new call (CANCELLED).
  absl::StatusOr<v1::Job> watched;
  absl::Notification watching;
  std::thread watcher([&] {
    watched = client.Watch(running, [&](const v1::JobEvent&) {
      if (!watching.HasBeenNotified()) watching.Notify();
    });
  });
  const bool watching_in_time = watching.WaitForNotificationWithTimeout(absl::Seconds(10));
  gate.open.Notify();  // the running job finishes within the grace period
  watcher.join();
  EXPECT_TRUE(watching_in_time) << "no first event";
  ASSERT_TRUE(watched.ok()) << watched.status();
  EXPECT_EQ(watched->state(), v1::JOB_STATE_SUCCEEDED);
  stopper.join();
}

// Past the grace period the running job is stopped and released: QUEUED
// again with its upload kept, to run after the next start (not CANCELLED:
// the client did not ask for that).
TEST(Server, ShutdownReleasesRunningJobsAfterTheGracePeriod) {
  Gate gate;
  TestServer server(
      {.workers = 1, .shutdown_grace = absl::Milliseconds(200), .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string running = client.Upload(path)->job_id();
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));
  absl::StatusOr<v1::Job> watched;
  absl::Notification watching;
  std::thread watcher([&] {
    watched = client.Watch(running, [&](const v1::JobEvent&) {
      if (!watching.HasBeenNotified()) watching.Notify();
    });
  });
  // The watch must be open before the job can end (as above).
  EXPECT_TRUE(watching.WaitForNotificationWithTimeout(absl::Seconds(10))) << "no first event";
  server.server().Shutdown();
  watcher.join();
  EXPECT_FALSE(watched.ok()) << "the watch ends with the server, not with a terminal state";
  EXPECT_EQ(server.SpoolFiles(), 1) << "the upload stays for the next start";
}

TEST(Server, FinishedJobsExpireAfterTheirTtl) {
  TestServer server({.result_ttl = absl::Milliseconds(300)});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  ASSERT_EQ(client.Watch(id)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(
      Eventually([&] { return client.GetJob(id).status().code() == absl::StatusCode::kNotFound; }));
  EXPECT_EQ(server.SpoolFiles(), 0);
}

}  // namespace
}  // namespace meshseg
