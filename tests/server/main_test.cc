// The meshseg-server binary: prints the bound address, refuses bad flags with
// one line, and on SIGTERM shuts down gracefully: health NOT_SERVING, new
// uploads refused, queued jobs kept for the next start, the running job
// finishes within the grace period (or is released after it, to run again
// after a restart), exit code 0. Its stderr holds
// one structured line per job state change.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/str_split.h"
#include "absl/synchronization/notification.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "scratch_dir.h"
#include "tests/server/server_process.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;
using ::testing::Not;
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::HealthStatus;
using testing_server::ServerProcess;

const std::string kServer = std::string(MESHSEG_BIN_DIR) + "/meshseg-server";
// Bound on every wait for the server. The jobs here take about a second on
// a quiet machine and over 15 s on a 2-core one running other builds; the
// bound only ends a test that would otherwise hang, so it is generous.
constexpr absl::Duration kTimeout = absl::Seconds(60);

// Returns the index of the first line of `log` holding every one of
// `parts`, or -1.
int LineOf(const std::vector<std::string>& log, std::initializer_list<std::string> parts) {
  for (int i = 0; i < static_cast<int>(log.size()); ++i) {
    bool all = true;
    for (const std::string& p : parts) all = all && log[i].find(p) != std::string::npos;
    if (all) return i;
  }
  return -1;
}

std::vector<std::string> LogLines(const std::string& log) {
  std::vector<std::string> lines = absl::StrSplit(log, '\n', absl::SkipEmpty());
  for (const std::string& line : lines) {
    EXPECT_THAT(line, MatchesRegex("ts=[0-9-]+T[0-9:.]+Z event=[a-z_]+( .*)?")) << "structured";
  }
  return lines;
}

// Watches a job on its own thread and channel; Open() returns once the
// first event came, so the job cannot end before the watch is in place.
class Watcher {
 public:
  Watcher(const std::string& address, const std::string& job_id)
      : thread_([this, address, job_id] {
          job_ = MeshsegClient::Connect(address).Watch(
              job_id,
              [this](const v1::JobEvent&) {
                if (!first_event_.HasBeenNotified()) first_event_.Notify();
              },
              kTimeout);
        }) {}
  ~Watcher() {
    if (thread_.joinable()) thread_.join();
  }
  bool Open() { return first_event_.WaitForNotificationWithTimeout(kTimeout); }
  absl::StatusOr<v1::Job> Job() {
    thread_.join();
    return job_;
  }

 private:
  absl::Notification first_event_;
  absl::StatusOr<v1::Job> job_;
  std::thread thread_;
};

// A part big enough that its job runs for about a second (test_piece at
// h = 0.5: ~180 k faces, 4.5 MB), written once for the suite.
class ServerMainJobs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    part_path_ = new std::string(testing_files::ScratchPath("test_piece.ply"));
    const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece", {.voxel_size = 0.5});
    ASSERT_TRUE(part.ok()) << part.status();
    part_faces_ = static_cast<int64_t>(part->mesh.tri.n_faces());
    ASSERT_TRUE(WriteMesh(part->mesh.tri, *part_path_).ok());
  }
  static void TearDownTestSuite() {
    delete part_path_;
    part_path_ = nullptr;
  }

  ServerMainJobs() {
    small_path_ = FreshDir("files") + "/box.off";
    testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), small_path_);
    spool_ = FreshDir("spool");
  }

  static std::string* part_path_;
  static int64_t part_faces_;
  std::string small_path_;
  std::string spool_;
};
std::string* ServerMainJobs::part_path_ = nullptr;
int64_t ServerMainJobs::part_faces_ = 0;

TEST(ServerMain, PrintsTheBoundPortAndStopsOnSigterm) {
  ServerProcess server({"--spool-dir", FreshDir("spool"), "--workers", "1"});
  EXPECT_THAT(server.first_line(), MatchesRegex("listening on 127\\.0\\.0\\.1:[0-9]+"));
  EXPECT_NE(server.first_line(), "listening on 127.0.0.1:0");
  ASSERT_FALSE(server.address().empty());
  server.Signal(SIGTERM);
  EXPECT_EQ(server.AwaitExit(kTimeout), 0);
  const std::vector<std::string> log = LogLines(server.Log());
  const int started = LineOf(log, {"event=server_started", "workers=1"});
  const int signal = LineOf(log, {"event=signal", "signal=SIGTERM"});
  const int done = LineOf(log, {"event=shutdown_done"});
  EXPECT_GE(started, 0) << server.Log();
  EXPECT_GT(signal, started) << server.Log();
  EXPECT_GT(done, signal) << server.Log();
}

// SIGHUP re-reads --auth-tokens: a token added to the file works after it,
// a removed one stops working; the process keeps running. (Without TLS the
// tokens ride gRPC local credentials, which the client's plaintext channel
// to 127.0.0.1 satisfies.)
TEST(ServerMain, SighupReloadsTheTokenFile) {
  const std::string tokens = FreshDir("auth") + "/tokens.txt";
  constexpr char kOld[] = "old-token-0123456789ab";
  constexpr char kNew[] = "new-token-0123456789ab";
  std::ofstream(tokens) << kOld << " acme\n";
  ServerProcess server({"--spool-dir", FreshDir("spool"), "--workers", "1", "--auth-tokens",
                        tokens});
  ASSERT_FALSE(server.address().empty()) << server.Log();
  const auto list_code = [&](const std::string& token) {
    absl::StatusOr<MeshsegClient> client = MeshsegClient::Connect(server.address(), {.token = token});
    if (!client.ok()) return client.status().code();
    client->set_call_timeout(absl::Seconds(5));
    return client->ListJobs().status().code();
  };
  EXPECT_EQ(list_code(kOld), absl::StatusCode::kOk);
  EXPECT_EQ(list_code(kNew), absl::StatusCode::kUnauthenticated);
  std::ofstream(tokens, std::ios::trunc) << kNew << " acme\n";
  server.Signal(SIGHUP);
  ASSERT_TRUE(server.AwaitLog("event=tokens_reloaded count=1", kTimeout)) << server.Log();
  EXPECT_EQ(list_code(kNew), absl::StatusCode::kOk);
  EXPECT_EQ(list_code(kOld), absl::StatusCode::kUnauthenticated);
  EXPECT_THAT(server.Log(), HasSubstr("transport=local"));
  server.Signal(SIGTERM);
  EXPECT_EQ(server.AwaitExit(kTimeout), 0);
}

// Runs the shell command `cmd`; returns its stdout and sets *exit_code.
std::string RunCommand(const std::string& cmd, int* exit_code) {
  std::string output;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) {
    *exit_code = -1;
    return output;
  }
  char buf[256];
  while (fgets(buf, sizeof buf, p)) output += buf;
  *exit_code = WEXITSTATUS(pclose(p));
  return output;
}

TEST(ServerMain, BadFlagValueExitsNonZero) {
  int exit_code = 0;
  const std::string output =
      RunCommand(kServer + " --listen 127.0.0.1:0 --queue-capacity 0 2>&1", &exit_code);
  EXPECT_NE(exit_code, 0);
  EXPECT_THAT(output, HasSubstr("--queue-capacity"));
}

// Returns the names of every ABSL_FLAG defined in server/*.cc, hyphenated
// as the command line spells them ("spool-dir").
std::vector<std::string> ServerFlagNames() {
  std::vector<std::string> names;
  const std::regex flag(R"(ABSL_FLAG\(\s*[^,]+,\s*(\w+)\s*,)");
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(MESHSEG_SOURCE_DIR) + "/server")) {
    if (entry.path().extension() != ".cc") continue;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::sregex_iterator it(text.begin(), text.end(), flag), end; it != end; ++it) {
      names.push_back(absl::StrReplaceAll((*it)[1].str(), {{"_", "-"}}));
    }
  }
  return names;
}

TEST(ServerMain, HelpDocumentsEveryFlagAndExitsZero) {
  const std::vector<std::string> names = ServerFlagNames();
  ASSERT_GE(names.size(), 7u) << "the flag scan found too few ABSL_FLAGs";
  for (const char* help : {"--help", "-h", "--helpfull"}) {
    int exit_code = -1;
    const std::string output =
        RunCommand(absl::StrCat(kServer, " ", help, " 2>/dev/null"), &exit_code);
    EXPECT_EQ(exit_code, 0) << help;
    EXPECT_THAT(output, HasSubstr("usage: meshseg-server")) << help;
    for (const std::string& name : names) {
      EXPECT_THAT(output, HasSubstr(absl::StrCat("  --", name))) << help << ": " << name;
    }
    EXPECT_THAT(output, HasSubstr("(default: \"127.0.0.1:50051\")\n      HOST:PORT to listen on"));
    EXPECT_THAT(output, Not(HasSubstr("--flagfile"))) << "only the server's own flags";
  }
}

// SIGTERM while a job runs and another waits: the waiting one stays queued
// (recovery_test.cc runs it after a restart), new uploads get UNAVAILABLE, health is NOT_SERVING,
// the running job finishes within the 50 s grace and the process exits 0. The log has each
// job's queued / started / finished lines, in order around the signal.
TEST_F(ServerMainJobs, SigtermLetsTheRunningJobFinishRefusesUploadsAndExitsZero) {
  ServerProcess server({"--spool-dir", spool_, "--workers", "1", "--shutdown-grace", "50s"});
  ASSERT_FALSE(server.address().empty()) << server.first_line() << server.Log();
  // Every channel here ends before the exit is awaited: the server gives
  // open connections up to 2 s to go away.
  std::string a, b;
  {
    MeshsegClient client = MeshsegClient::Connect(server.address());
    const absl::StatusOr<v1::UploadResponse> running = client.Upload(*part_path_);
    ASSERT_TRUE(running.ok()) << running.status();
    a = running->job_id();
    ASSERT_TRUE(server.AwaitLog("event=job_started job=" + a, kTimeout)) << server.Log();
    const absl::StatusOr<v1::UploadResponse> queued = client.Upload(small_path_);
    ASSERT_TRUE(queued.ok()) << queued.status();
    b = queued->job_id();
  }
  Watcher watch_a(server.address(), a);
  ASSERT_TRUE(watch_a.Open());

  const absl::Time sigterm = absl::Now();
  server.Signal(SIGTERM);
  ASSERT_TRUE(server.AwaitLog("event=shutdown_started", kTimeout)) << server.Log();
  // The log line comes first; health turns NOT_SERVING once uploads are refused.
  ASSERT_TRUE(Eventually([&] { return HealthStatus(server.address()) == 2; }))
      << "NOT_SERVING while the job finishes";
  const absl::StatusOr<v1::UploadResponse> refused =
      MeshsegClient::Connect(server.address()).Upload(small_path_);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kUnavailable) << refused.status();
  EXPECT_THAT(refused.status().message(), HasSubstr("shutting down"));

  const absl::StatusOr<v1::Job> job_a = watch_a.Job();
  ASSERT_TRUE(job_a.ok()) << job_a.status();
  EXPECT_EQ(job_a->state(), v1::JOB_STATE_SUCCEEDED) << job_a->error_message();
  EXPECT_EQ(job_a->face_count(), part_faces_);

  EXPECT_EQ(server.AwaitExit(kTimeout), 0);
  // Finishing within the grace is what job_a's SUCCEEDED shows (past the
  // grace it would be released, not finished); the time is only recorded,
  // never asserted: it depends on the machine's load.
  const absl::Duration stop_time = absl::Now() - sigterm;
  RecordProperty("sigterm_to_exit_ms", static_cast<int>(absl::ToInt64Milliseconds(stop_time)));

  const std::vector<std::string> log = LogLines(server.Log());
  const int queued_a = LineOf(log, {"event=job_queued", "job=" + a, "file=test_piece.ply"});
  const int started_a = LineOf(log, {"event=job_started", "job=" + a});
  const int queued_b = LineOf(log, {"event=job_queued", "job=" + b, "file=box.off"});
  const int signal = LineOf(log, {"event=signal", "signal=SIGTERM"});
  const int shutdown = LineOf(log, {"event=shutdown_started", "grace=50s"});
  const int rejected = LineOf(log, {"event=upload_rejected", "code=UNAVAILABLE"});
  const int finished_a = LineOf(log, {"event=job_finished", "job=" + a, "state=SUCCEEDED",
                                      absl::StrCat("faces=", part_faces_)});
  const int done = LineOf(log, {"event=shutdown_done"});
  const std::string all = server.Log();
  // job_queued is logged after the push, so a free worker may log
  // job_started first: only their presence is checked.
  EXPECT_GE(queued_a, 0) << all;
  EXPECT_GE(started_a, 0) << all;
  EXPECT_GT(queued_b, started_a) << all;
  EXPECT_GT(signal, queued_b) << all;
  EXPECT_GT(shutdown, signal) << all;
  EXPECT_GT(rejected, shutdown) << all;
  EXPECT_GT(finished_a, signal) << "the job was still running at SIGTERM\n" << all;
  EXPECT_GT(done, finished_a) << all;
  EXPECT_EQ(LineOf(log, {"event=job_started", "job=" + b}), -1) << "the queued job never ran";
  EXPECT_THAT(all, Not(HasSubstr("job=" + b + " state=CANCELLED"))) << "nor was cancelled";
  EXPECT_THAT(all, Not(HasSubstr("shutdown_releasing_running_jobs")));
}

// With a 100 ms grace the running job is stopped and released, not
// cancelled: the process exits 0 promptly, the log says so, its upload stays
// in the spool, and the next start runs it again to SUCCEEDED without
// counting the interrupted attempt.
TEST_F(ServerMainJobs, SigtermReleasesTheRunningJobAfterTheGraceAndTheNextStartRunsIt) {
  std::string a;
  {
    ServerProcess server({"--spool-dir", spool_, "--workers", "1", "--shutdown-grace", "100ms"});
    ASSERT_FALSE(server.address().empty()) << server.first_line() << server.Log();
    const absl::StatusOr<v1::UploadResponse> running =
        MeshsegClient::Connect(server.address()).Upload(*part_path_);
    ASSERT_TRUE(running.ok()) << running.status();
    a = running->job_id();
    ASSERT_TRUE(server.AwaitLog("event=job_started job=" + a, kTimeout)) << server.Log();

    const absl::Time sigterm = absl::Now();
    server.Signal(SIGTERM);
    EXPECT_EQ(server.AwaitExit(kTimeout), 0);
    // Not waiting for the job is what the job_released line below shows; the
    // time is recorded only (it depends on the machine's load).
    const absl::Duration stop_time = absl::Now() - sigterm;
    RecordProperty("sigterm_to_exit_ms", static_cast<int>(absl::ToInt64Milliseconds(stop_time)));

    const std::vector<std::string> log = LogLines(server.Log());
    const std::string all = server.Log();
    const int signal = LineOf(log, {"event=signal", "signal=SIGTERM"});
    const int releasing = LineOf(log, {"event=shutdown_releasing_running_jobs"});
    const int released = LineOf(log, {"event=job_released", "job=" + a});
    const int done = LineOf(log, {"event=shutdown_done"});
    EXPECT_GT(releasing, signal) << all;
    EXPECT_GT(released, releasing) << all;
    EXPECT_GT(done, released) << all;
    EXPECT_EQ(LineOf(log, {"event=job_finished", "job=" + a}), -1) << all;
  }
  ServerProcess again({"--spool-dir", spool_, "--workers", "1"});
  ASSERT_FALSE(again.address().empty()) << again.Log();
  const absl::StatusOr<v1::Job> job =
      MeshsegClient::Connect(again.address()).Watch(a, {}, kTimeout);
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED) << job->error_message();
  EXPECT_EQ(job->face_count(), part_faces_);
  EXPECT_EQ(job->attempts(), 1) << "the released attempt is not counted";
}

}  // namespace
}  // namespace meshseg
