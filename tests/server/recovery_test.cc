// The embedded mode is durable: real meshseg-server processes on one spool,
// killed with SIGKILL or stopped with SIGTERM and started again. Every
// accepted job ends SUCCEEDED with the result an offline `meshseg segment`
// gives (byte for byte), finished jobs are served without running again,
// and a poison input ends FAILED after --max-attempts while the jobs behind
// it complete.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "client/meshseg_client.h"
#include "scratch_dir.h"
#include "tests/server/offline_result.h"
#include "tests/server/server_process.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::ServerJson;
using testing_server::ServerProcess;
using testing_server::TestPart;

// Bound on every wait; the jobs here take 0.1 to 1 s.
constexpr absl::Duration kTimeout = absl::Seconds(60);

class Recovery : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    parts_ = new std::vector<TestPart>(
        testing_server::MakeTestParts(testing_files::ScratchPath("recovery_parts")));
  }
  static void TearDownTestSuite() { delete parts_; }

  void SetUp() override {
    for (const TestPart& p : *parts_) ASSERT_FALSE(p.offline_json.empty()) << p.path;
    spool_ = FreshDir("spool");
  }

  static const TestPart& Small(int i) { return (*parts_)[i]; }
  static const TestPart& Long() { return (*parts_)[3]; }

  static v1::Job ExpectOfflineResult(MeshsegClient& client, const std::string& id,
                                     const TestPart& part) {
    return testing_server::ExpectOfflineResult(client, id, part, kTimeout);
  }

  static std::vector<TestPart>* parts_;
  std::string spool_;
};
std::vector<TestPart>* Recovery::parts_ = nullptr;

std::string Upload(MeshsegClient& client, const std::string& path) {
  const absl::StatusOr<v1::UploadResponse> up = client.Upload(path);
  EXPECT_TRUE(up.ok()) << path << ": " << up.status();
  return up.ok() ? up->job_id() : "";
}

TEST_F(Recovery, KillNineWithJobsFinishedRunningAndQueuedEveryJobSucceedsAfterRestart) {
  std::string done, running;
  std::vector<std::string> queued;
  std::string done_json;
  {
    ServerProcess first({"--spool-dir", spool_, "--workers", "1"});
    ASSERT_FALSE(first.address().empty()) << first.Log();
    MeshsegClient client = MeshsegClient::Connect(first.address());
    done = Upload(client, Small(0).path);
    ExpectOfflineResult(client, done, Small(0));
    running = Upload(client, Long().path);
    ASSERT_TRUE(first.AwaitLog("event=job_started job=" + running, kTimeout)) << first.Log();
    queued = {Upload(client, Small(1).path), Upload(client, Small(2).path)};
    first.Kill9();
    EXPECT_THAT(first.Log(), ::testing::Not(HasSubstr("event=job_finished job=" + running)))
        << "the long job was still running at kill -9";
  }

  ServerProcess second({"--spool-dir", spool_, "--workers", "1"});
  ASSERT_FALSE(second.address().empty()) << second.Log();
  EXPECT_TRUE(second.AwaitLog("requeued=3 interrupted=1 served=1 expired=0", kTimeout))
      << second.Log();
  MeshsegClient client = MeshsegClient::Connect(second.address());
  EXPECT_EQ(ExpectOfflineResult(client, running, Long()).attempts(), 2) << "run again";
  EXPECT_EQ(ExpectOfflineResult(client, queued[0], Small(1)).attempts(), 1);
  EXPECT_EQ(ExpectOfflineResult(client, queued[1], Small(2)).attempts(), 1);
  EXPECT_EQ(ExpectOfflineResult(client, done, Small(0)).attempts(), 1);
  EXPECT_THAT(second.Log(), ::testing::Not(HasSubstr("event=job_started job=" + done)))
      << "a finished job is served, not run again";

  // Oldest first, as accepted.
  const absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  std::vector<std::string> order;
  for (const v1::Job& j : *jobs) order.push_back(j.job_id());
  EXPECT_EQ(order, (std::vector<std::string>{done, running, queued[0], queued[1]}));
}

// SIGTERM lets the running job finish and keeps the queued ones (they are
// not cancelled); the next start runs them.
TEST_F(Recovery, SigtermKeepsQueuedJobsForTheNextStart) {
  std::string running;
  std::vector<std::string> queued;
  {
    ServerProcess first({"--spool-dir", spool_, "--workers", "1", "--shutdown-grace", "20s"});
    ASSERT_FALSE(first.address().empty()) << first.Log();
    MeshsegClient client = MeshsegClient::Connect(first.address());
    running = Upload(client, Long().path);
    ASSERT_TRUE(first.AwaitLog("event=job_started job=" + running, kTimeout)) << first.Log();
    queued = {Upload(client, Small(0).path), Upload(client, Small(1).path)};
    first.Signal(SIGTERM);
    EXPECT_EQ(first.AwaitExit(kTimeout), 0);
    EXPECT_TRUE(first.AwaitLog("event=job_finished job=" + running + " state=SUCCEEDED", kTimeout))
        << first.Log();
    for (const std::string& id : queued) {
      EXPECT_THAT(first.Log(), ::testing::Not(HasSubstr("job=" + id + " state=CANCELLED")));
    }
  }
  ServerProcess second({"--spool-dir", spool_, "--workers", "1"});
  ASSERT_FALSE(second.address().empty()) << second.Log();
  EXPECT_TRUE(second.AwaitLog("requeued=2 interrupted=0 served=1", kTimeout)) << second.Log();
  MeshsegClient client = MeshsegClient::Connect(second.address());
  EXPECT_EQ(ExpectOfflineResult(client, queued[0], Small(0)).attempts(), 1);
  EXPECT_EQ(ExpectOfflineResult(client, queued[1], Small(1)).attempts(), 1);
  ExpectOfflineResult(client, running, Long());
  EXPECT_THAT(second.Log(), ::testing::Not(HasSubstr("event=job_started job=" + running)));
}

// A test-only poison input aborts the worker process each time it starts
// (MESHSEG_TEST_ABORT_ON_FILE). Restarted after each crash, as a supervisor
// would, the server gives up on it after --max-attempts 3 starts; the jobs
// queued behind it complete.
TEST_F(Recovery, PoisonJobEndsFailedAfterMaxAttemptsAndTheJobsBehindItComplete) {
  const std::string poison = FreshDir("poison") + "/poison.ply";
  std::filesystem::copy_file(Small(0).path, poison);
  const std::vector<std::string> flags = {"--spool-dir", spool_,           "--workers",
                                          "1",           "--max-attempts", "3"};
  const std::vector<std::string> env = {"MESHSEG_TEST_ABORT_ON_FILE=poison.ply"};
  auto server = std::make_unique<ServerProcess>(flags, env);
  ASSERT_FALSE(server->address().empty()) << server->Log();
  std::string poison_id;
  std::vector<std::string> behind;
  {
    MeshsegClient client = MeshsegClient::Connect(server->address());
    Upload(client, Long().path);  // keeps the worker busy while the rest is queued
    poison_id = Upload(client, poison);
    behind = {Upload(client, Small(1).path), Upload(client, Small(2).path)};
  }
  int crashes = 0;
  absl::StatusOr<v1::Job> verdict = absl::UnknownError("not watched");
  while (crashes <= 3) {
    MeshsegClient client = MeshsegClient::Connect(server->address());
    verdict = client.Watch(poison_id, {}, kTimeout);
    if (verdict.ok()) break;
    // The watch broke: the worker aborted on the poison input.
    ASSERT_EQ(server->AwaitExit(kTimeout), -1) << "killed by SIGABRT\n" << server->Log();
    // The log reader may still be draining the pipe after the exit.
    EXPECT_TRUE(server->AwaitLog("event=test_abort_on_file job=" + poison_id, kTimeout))
        << server->Log();
    ++crashes;
    server = std::make_unique<ServerProcess>(flags, env);
    ASSERT_FALSE(server->address().empty()) << server->Log();
  }
  EXPECT_EQ(crashes, 3);
  ASSERT_TRUE(verdict.ok()) << verdict.status();
  EXPECT_EQ(verdict->state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(verdict->attempts(), 3);
  EXPECT_THAT(verdict->error_message(), HasSubstr("worker died 3 times"));
  MeshsegClient client = MeshsegClient::Connect(server->address());
  ExpectOfflineResult(client, behind[0], Small(1));
  ExpectOfflineResult(client, behind[1], Small(2));
}

}  // namespace
}  // namespace meshseg
