// Tenant isolation over loopback gRPC with bearer tokens, in both backends
// (embedded spool, and Redis with a real redis-server): a job belongs to the
// tenant that uploaded it; every call on another tenant's job answers
// NOT_FOUND with the message of an unknown id; ListJobs shows the caller's
// jobs only, a page at a time, optionally one state only.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "client/meshseg_client.h"
#include "server/job_store.h"
#include "tests/server/redis_process.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg::server {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;

constexpr char kAlice[] = "alice-token-0123456789";
constexpr char kBob[] = "bob-token-0123456789ab";

enum class Backend { kEmbedded, kRedis };

class Tenants : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    const std::string tokens = FreshDir("auth") + "/tokens.txt";
    std::ofstream(tokens) << kAlice << " alice\n" << kBob << " bob\n";
    mesh_ = FreshDir("mesh") + "/box.stl";
    testing_files::WriteStlBinary(testing_files::SplitBox(2, {1, 1, 1}), mesh_);
    ServerOptions options;
    options.workers = 1;
    options.runner = gate_.Runner();
    options.security.auth_tokens = tokens;
    if (GetParam() == Backend::kRedis) {
      redis_ = std::make_unique<testing_server::RedisProcess>(FreshDir("redis"));
      ASSERT_TRUE(redis_->ok()) << "redis-server did not start";
      options.queue = redis_->url();
      options.blob_dir = FreshDir("blobs");
    }
    server_ = std::make_unique<testing_server::TestServer>(std::move(options));
  }
  void TearDown() override {
    if (!gate_.open.HasBeenNotified()) gate_.open.Notify();
    server_.reset();
  }

  MeshsegClient As(const char* token) {
    absl::StatusOr<MeshsegClient> client =
        MeshsegClient::Connect(server_->address(), {.token = token});
    EXPECT_TRUE(client.ok()) << client.status();
    client->set_call_timeout(absl::Seconds(20));
    return *std::move(client);
  }

  std::string Upload(MeshsegClient& client) {
    absl::StatusOr<v1::UploadResponse> up = client.Upload(mesh_);
    EXPECT_TRUE(up.ok()) << up.status();
    return up.ok() ? up->job_id() : "";
  }

  static std::vector<std::string> Ids(const std::vector<v1::Job>& jobs) {
    std::vector<std::string> ids;
    for (const v1::Job& job : jobs) ids.push_back(job.job_id());
    return ids;
  }

  Gate gate_;
  std::string mesh_;
  std::unique_ptr<testing_server::RedisProcess> redis_;
  std::unique_ptr<testing_server::TestServer> server_;
};

// The status of every call bob can make on `id`, all NOT_FOUND with the
// unknown-id message.
void ExpectHidden(MeshsegClient& bob, const std::string& id) {
  const std::string message(JobNotFound(id).message());
  const auto expect = [&](const absl::Status& s, const char* call) {
    EXPECT_EQ(s.code(), absl::StatusCode::kNotFound) << call << ": " << s;
    EXPECT_EQ(s.message(), message) << call;
  };
  expect(bob.GetJob(id).status(), "GetJob");
  expect(bob.Watch(id, [](const v1::JobEvent&) {}).status(), "WatchJob");
  expect(bob.Result(id).status(), "GetResult");
  expect(bob.Cancel(id).status(), "CancelJob");
}

TEST_P(Tenants, AnotherTenantsJobsAreNotFoundForEveryCallAndNotListed) {
  MeshsegClient alice = As(kAlice);
  MeshsegClient bob = As(kBob);
  const std::string running = Upload(alice);
  const std::string queued = Upload(alice);
  ASSERT_TRUE(Eventually([&] { return gate_.entered == 1; }));

  for (const std::string& id : {running, queued}) ExpectHidden(bob, id);
  // Bob's cancel did nothing.
  EXPECT_EQ(alice.GetJob(running)->state(), v1::JOB_STATE_RUNNING);
  EXPECT_EQ(alice.GetJob(queued)->state(), v1::JOB_STATE_QUEUED);
  EXPECT_EQ(alice.GetJob(queued)->tenant(), "alice");
  const std::string own = Upload(bob);
  EXPECT_THAT(Ids(*bob.ListJobs()), ElementsAre(own));
  EXPECT_THAT(Ids(*alice.ListJobs()), ::testing::UnorderedElementsAre(running, queued));

  gate_.open.Notify();
  const absl::StatusOr<v1::Job> done = alice.Watch(running, [](const v1::JobEvent&) {});
  ASSERT_TRUE(done.ok()) << done.status();
  ASSERT_EQ(done->state(), v1::JOB_STATE_SUCCEEDED);
  ExpectHidden(bob, running);  // GetResult of a finished job too
  EXPECT_TRUE(alice.Result(running).ok());
  EXPECT_EQ(alice.GetJob(running)->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_EQ(alice.GetJob(running)->result_sha256().size(), 64u);  // kept by both stores
}

TEST_P(Tenants, ListJobsPagesThroughOwnJobsAndFiltersByState) {
  MeshsegClient alice = As(kAlice);
  MeshsegClient bob = As(kBob);
  std::set<std::string> uploaded;
  for (int i = 0; i < 7; ++i) uploaded.insert(Upload(alice));
  (void)Upload(bob);
  ASSERT_TRUE(Eventually([&] { return gate_.entered == 1; }));
  // Cancel two queued jobs (the running one is the gate's).
  std::vector<std::string> cancelled;
  for (const std::string& id : uploaded) {
    if (cancelled.size() < 2 && alice.GetJob(id)->state() == v1::JOB_STATE_QUEUED) {
      ASSERT_TRUE(alice.Cancel(id).ok());
      cancelled.push_back(id);
    }
  }

  std::vector<v1::Job> all;
  std::vector<int> sizes;
  v1::ListJobsRequest request;
  request.set_page_size(3);
  do {
    const absl::StatusOr<v1::ListJobsResponse> page = alice.ListJobsPage(request);
    ASSERT_TRUE(page.ok()) << page.status();
    sizes.push_back(page->jobs_size());
    all.insert(all.end(), page->jobs().begin(), page->jobs().end());
    request.set_page_token(page->next_page_token());
  } while (!request.page_token().empty() && sizes.size() < 10);
  EXPECT_THAT(sizes, ElementsAre(3, 3, 1));
  const std::vector<std::string> ids = Ids(all);
  EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()), uploaded);
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end(), [](const v1::Job& a, const v1::Job& b) {
    return std::make_tuple(a.created_unix_ms(), a.job_id()) <
           std::make_tuple(b.created_unix_ms(), b.job_id());
  }));

  const auto in_state = [&](v1::JobState state) {
    v1::ListJobsRequest r;
    r.set_state(state);
    absl::StatusOr<v1::ListJobsResponse> page = alice.ListJobsPage(r);
    EXPECT_TRUE(page.ok()) << page.status();
    return page.ok() ? Ids({page->jobs().begin(), page->jobs().end()}) : std::vector<std::string>{};
  };
  EXPECT_THAT(in_state(v1::JOB_STATE_CANCELLED), ::testing::UnorderedElementsAreArray(cancelled));
  EXPECT_EQ(in_state(v1::JOB_STATE_QUEUED).size(), 4u);
  EXPECT_EQ(in_state(v1::JOB_STATE_RUNNING).size(), 1u);
  EXPECT_THAT(in_state(v1::JOB_STATE_SUCCEEDED), IsEmpty());

  v1::ListJobsRequest bad;
  bad.set_page_size(5000);
  EXPECT_EQ(alice.ListJobsPage(bad).status().code(), absl::StatusCode::kInvalidArgument);
  bad.set_page_size(0);
  bad.set_page_token("not a token");
  EXPECT_EQ(alice.ListJobsPage(bad).status().code(), absl::StatusCode::kInvalidArgument);
}

// A retried upload (same request_id, same tenant) gets the job the first
// created, also while many retries race; another tenant's same id is its own.
TEST_P(Tenants, ARetriedUploadWithTheSameRequestIdGetsTheSameJob) {
  MeshsegClient alice = As(kAlice);
  MeshsegClient bob = As(kBob);
  const UploadOptions once{.request_id = "order-4711/attempt"};
  const absl::StatusOr<v1::UploadResponse> first = alice.Upload(mesh_, once);
  ASSERT_TRUE(first.ok()) << first.status();
  std::vector<std::string> retried(6);
  std::vector<std::thread> threads;
  for (int i = 0; i < 6; ++i) {
    threads.emplace_back([&, i] {
      MeshsegClient c = As(kAlice);
      absl::StatusOr<v1::UploadResponse> up = c.Upload(mesh_, once);
      if (up.ok()) retried[i] = up->job_id();
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_THAT(retried, ::testing::Each(first->job_id()));
  EXPECT_EQ(alice.ListJobs()->size(), 1u);
  EXPECT_EQ(alice.GetJob(first->job_id())->request_id(), once.request_id);

  const absl::StatusOr<v1::UploadResponse> bobs = bob.Upload(mesh_, once);
  ASSERT_TRUE(bobs.ok());
  EXPECT_NE(bobs->job_id(), first->job_id());
  const absl::StatusOr<v1::UploadResponse> other = alice.Upload(mesh_, {.request_id = "another"});
  ASSERT_TRUE(other.ok());
  EXPECT_NE(other->job_id(), first->job_id());
  EXPECT_EQ(alice.Upload(mesh_, {.request_id = "has space"}).status().code(),
            absl::StatusCode::kInvalidArgument);
}

INSTANTIATE_TEST_SUITE_P(Backends, Tenants, ::testing::Values(Backend::kEmbedded, Backend::kRedis),
                         [](const auto& info) {
                           return info.param == Backend::kEmbedded ? "Embedded" : "Redis";
                         });

}  // namespace
}  // namespace meshseg::server
