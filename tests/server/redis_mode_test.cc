// The Redis mode with real processes: a redis-server (AOF on) and
// meshseg-server replicas in the api and worker roles sharing a blob folder.
// Any replica answers for any job; a killed worker's job completes on the
// other worker; a killed and restarted Redis loses no accepted job; a
// killed api replica's jobs are watched and fetched through the other.
// Results are compared byte for byte with an offline `meshseg segment`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "client/meshseg_client.h"
#include "scratch_dir.h"
#include "tests/server/offline_result.h"
#include "tests/server/redis_process.h"
#include "tests/server/server_process.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::RedisProcess;
using testing_server::ServerJson;
using testing_server::ServerProcess;
using testing_server::TestPart;

constexpr absl::Duration kTimeout = absl::Seconds(60);

class RedisMode : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    parts_ = new std::vector<TestPart>(
        testing_server::MakeTestParts(testing_files::ScratchPath("redis_mode_parts")));
  }
  static void TearDownTestSuite() { delete parts_; }

  void SetUp() override {
    for (const TestPart& p : *parts_) ASSERT_FALSE(p.offline_json.empty()) << p.path;
    redis_ = std::make_unique<RedisProcess>(FreshDir("redis"));
    ASSERT_TRUE(redis_->ok()) << "redis-server did not start";
    blobs_ = FreshDir("blobs");
    for (int i = 0; i < 2; ++i) {
      apis_.push_back(Start("api", "api" + std::to_string(i)));
      workers_.push_back(Start("worker", "worker" + std::to_string(i)));
    }
  }

  std::unique_ptr<ServerProcess> Start(const std::string& role, const std::string& name,
                                       std::vector<std::string> env = {}) {
    auto p = std::make_unique<ServerProcess>(
        std::vector<std::string>{"--role", role, "--queue", redis_->url(), "--blob-dir", blobs_,
                                 "--spool-dir", FreshDir(name), "--workers", "1", "--claim-after",
                                 "2s", "--shutdown-grace", "1s"},
        std::move(env));
    EXPECT_FALSE(p->address().empty()) << p->first_line() << p->Log();
    return p;
  }

  MeshsegClient Api(int i) const { return MeshsegClient::Connect(apis_[i]->address()); }

  static const TestPart& Small(int i) { return (*parts_)[i]; }
  static const TestPart& Long() { return (*parts_)[3]; }

  static v1::Job ExpectOfflineResult(MeshsegClient client, const std::string& id,
                                     const TestPart& part) {
    return testing_server::ExpectOfflineResult(client, id, part, kTimeout);
  }

  // Index of the worker whose log shows `id` started, or -1 after 30 s.
  int WorkerRunning(const std::string& id) const {
    const absl::Time deadline = absl::Now() + absl::Seconds(30);
    while (absl::Now() < deadline) {
      for (int i = 0; i < static_cast<int>(workers_.size()); ++i) {
        if (workers_[i]->Log().find("event=job_started job=" + id) != std::string::npos) return i;
      }
      absl::SleepFor(absl::Milliseconds(10));
    }
    return -1;
  }

  static std::vector<TestPart>* parts_;
  std::unique_ptr<RedisProcess> redis_;
  std::string blobs_;
  std::vector<std::unique_ptr<ServerProcess>> apis_;
  std::vector<std::unique_ptr<ServerProcess>> workers_;
};
std::vector<TestPart>* RedisMode::parts_ = nullptr;

// 8 clients x 3 jobs, each client alternating between the two api replicas
// for upload and for watch/fetch; both workers share the work.
TEST_F(RedisMode, TwentyFourJobsFromEightClientsThroughBothApisAreByteIdenticalToOffline) {
  constexpr int kClients = 8;
  constexpr int kJobsPerClient = 3;
  std::vector<std::string> errors(kClients);
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      for (int j = 0; j < kJobsPerClient; ++j) {
        const int k = c * kJobsPerClient + j;
        const TestPart& part = Small(k % 3);
        MeshsegClient up_client = Api(k % 2);
        MeshsegClient watch_client = Api((k + 1) % 2);
        const absl::StatusOr<v1::UploadResponse> up = up_client.Upload(part.path);
        if (!up.ok()) {
          errors[c] += up.status().ToString() + "; ";
          continue;
        }
        const absl::StatusOr<v1::Job> job = watch_client.Watch(up->job_id(), {}, kTimeout);
        const absl::StatusOr<std::string> json = ServerJson(watch_client, up->job_id());
        if (!job.ok() || job->state() != v1::JOB_STATE_SUCCEEDED || !json.ok()) {
          errors[c] += "job " + up->job_id() + " did not succeed; ";
        } else if (*json != part.offline_json) {
          errors[c] += "job " + up->job_id() + " differs from offline; ";
        }
      }
    });
  }
  for (std::thread& t : clients) t.join();
  for (int c = 0; c < kClients; ++c) EXPECT_EQ(errors[c], "") << "client " << c;
  for (int a = 0; a < 2; ++a) {
    const absl::StatusOr<std::vector<v1::Job>> jobs = Api(a).ListJobs();
    ASSERT_TRUE(jobs.ok()) << jobs.status();
    EXPECT_EQ(jobs->size(), static_cast<std::size_t>(kClients * kJobsPerClient))
        << "replica " << a << " lists every job";
  }
  for (int w = 0; w < 2; ++w) {
    EXPECT_TRUE(workers_[w]->AwaitLog("event=job_finished", kTimeout)) << "worker " << w << " idle";
  }
}

TEST_F(RedisMode, KillNineOfTheWorkerRunningAJobItCompletesOnTheOther) {
  const absl::StatusOr<v1::UploadResponse> up = Api(0).Upload(Long().path);
  ASSERT_TRUE(up.ok()) << up.status();
  const int victim = WorkerRunning(up->job_id());
  ASSERT_GE(victim, 0);
  workers_[victim]->Kill9();
  const v1::Job job = ExpectOfflineResult(Api(1), up->job_id(), Long());
  EXPECT_EQ(job.attempts(), 2) << "the takeover is a new attempt";
  const ServerProcess& other = *workers_[1 - victim];
  EXPECT_TRUE(other.AwaitLog("event=job_reclaimed job=" + up->job_id(), kTimeout)) << other.Log();
  EXPECT_TRUE(
      other.AwaitLog("event=job_finished job=" + up->job_id() + " state=SUCCEEDED", kTimeout))
      << other.Log();
}

// Redis dies while jobs are queued and running: new uploads are refused
// with UNAVAILABLE naming Redis, no process exits, and once Redis is back
// (from its AOF) every accepted job completes.
TEST_F(RedisMode, KillNineOfRedisMidRunLosesNoAcceptedJob) {
  std::vector<std::pair<std::string, const TestPart*>> accepted;
  for (int k = 0; k < 6; ++k) {
    const TestPart& part = k == 0 ? Long() : Small(k % 3);
    const absl::StatusOr<v1::UploadResponse> up = Api(k % 2).Upload(part.path);
    ASSERT_TRUE(up.ok()) << up.status();
    accepted.emplace_back(up->job_id(), &part);
  }
  ASSERT_GE(WorkerRunning(accepted[0].first), 0);
  redis_->Kill9();
  const absl::StatusOr<v1::UploadResponse> refused = Api(0).Upload(Small(0).path);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kUnavailable) << refused.status();
  EXPECT_THAT(refused.status().message(), HasSubstr("redis"));
  absl::SleepFor(absl::Seconds(1));  // workers see the outage
  ASSERT_TRUE(redis_->Restart()) << "redis-server did not come back";
  for (const auto& [id, part] : accepted) ExpectOfflineResult(Api(1), id, *part);
  for (const auto& p : apis_) EXPECT_FALSE(p->AwaitExit(absl::ZeroDuration()).has_value());
  for (const auto& p : workers_) EXPECT_FALSE(p->AwaitExit(absl::ZeroDuration()).has_value());
}

TEST_F(RedisMode, KillNineOfAnApiReplicaItsJobsAreWatchedAndFetchedThroughTheOther) {
  std::vector<std::pair<std::string, const TestPart*>> jobs;
  for (int k = 0; k < 3; ++k) {
    const absl::StatusOr<v1::UploadResponse> up = Api(0).Upload(Small(k).path);
    ASSERT_TRUE(up.ok()) << up.status();
    jobs.emplace_back(up->job_id(), &Small(k));
  }
  apis_[0]->Kill9();
  for (const auto& [id, part] : jobs) ExpectOfflineResult(Api(1), id, *part);
}

// A cancel sent to one api replica stops the job on whichever worker runs it.
TEST_F(RedisMode, CancelThroughEitherReplicaStopsTheRunningJob) {
  const absl::StatusOr<v1::UploadResponse> up = Api(0).Upload(Long().path);
  ASSERT_TRUE(up.ok()) << up.status();
  const int worker = WorkerRunning(up->job_id());
  ASSERT_GE(worker, 0);
  const absl::Time sent = absl::Now();
  const absl::StatusOr<v1::Job> cancel = Api(1).Cancel(up->job_id());
  ASSERT_TRUE(cancel.ok()) << cancel.status();
  const absl::StatusOr<v1::Job> job = Api(0).Watch(up->job_id(), {}, kTimeout);
  ASSERT_TRUE(job.ok()) << job.status();
  RecordProperty("cancel_to_terminal_ms",
                 static_cast<int>(absl::ToInt64Milliseconds(absl::Now() - sent)));
  // The cancel returned OK, so the job was still running: it must end
  // CANCELLED, not finish.
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED) << job->error_message();
  EXPECT_TRUE(workers_[worker]->AwaitLog(
      "event=job_finished job=" + up->job_id() + " state=CANCELLED", absl::Seconds(10)))
      << workers_[worker]->Log();
}

// A test-only poison input (MESHSEG_TEST_ABORT_ON_FILE) aborts whichever
// worker takes it. Dead workers are started again, as a Deployment would;
// each takeover (XAUTOCLAIM after --claim-after) is an attempt, and after
// --max-attempts 3 the job ends FAILED while the jobs behind it complete.
TEST_F(RedisMode, PoisonJobEndsFailedAfterMaxAttemptsAndTheJobsBehindItComplete) {
  const std::vector<std::string> env = {"MESHSEG_TEST_ABORT_ON_FILE=poison.ply"};
  for (int w = 0; w < 2; ++w) workers_[w] = Start("worker", "poisoned" + std::to_string(w), env);
  const std::string poison = FreshDir("poison") + "/poison.ply";
  std::filesystem::copy_file(Small(0).path, poison);
  const absl::StatusOr<v1::UploadResponse> bad = Api(0).Upload(poison);
  ASSERT_TRUE(bad.ok()) << bad.status();
  std::vector<std::pair<std::string, const TestPart*>> behind;
  for (int k = 1; k < 3; ++k) {
    const absl::StatusOr<v1::UploadResponse> up = Api(k % 2).Upload(Small(k).path);
    ASSERT_TRUE(up.ok()) << up.status();
    behind.emplace_back(up->job_id(), &Small(k));
  }
  int restarts = 0;
  absl::StatusOr<v1::Job> verdict = absl::UnknownError("not read");
  const absl::Time deadline = absl::Now() + kTimeout;
  while (absl::Now() < deadline) {
    verdict = Api(1).GetJob(bad->job_id());
    if (verdict.ok() && verdict->state() == v1::JOB_STATE_FAILED) break;
    for (int w = 0; w < 2; ++w) {
      if (!workers_[w]->AwaitExit(absl::ZeroDuration()).has_value()) continue;
      ++restarts;
      workers_[w] =
          Start("worker", "poisoned" + std::to_string(w) + "_" + std::to_string(restarts), env);
    }
    absl::SleepFor(absl::Milliseconds(50));
  }
  ASSERT_TRUE(verdict.ok()) << verdict.status();
  EXPECT_EQ(verdict->state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(verdict->attempts(), 3);
  EXPECT_THAT(verdict->error_message(), HasSubstr("worker died 3 times"));
  EXPECT_EQ(restarts, 3) << "one worker process died per attempt";
  for (const auto& [id, part] : behind) ExpectOfflineResult(Api(0), id, *part);
}

}  // namespace
}  // namespace meshseg
