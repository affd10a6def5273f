// meshseg-server as an operator sees it: a real process on loopback with
// --metrics-listen and --log-format json. /metrics is scraped while a job
// runs and after jobs succeeded, failed, were cancelled while queued and
// were refused at upload; the counters and histograms move by exactly those
// jobs, every scrape passes `promtool check metrics`, and every log line
// parses with python3's json module (check_json_log.py).
#include <signal.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "scratch_dir.h"
#include "tests/server/http_get.h"
#include "tests/server/server_process.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::HttpBody;
using testing_server::HttpGet;
using testing_server::ServerProcess;

constexpr absl::Duration kTimeout = absl::Seconds(60);

// The value of the sample `series` (name and labels as written), or NaN.
double Sample(const std::string& text, const std::string& series) {
  const std::string prefix = "\n" + series + " ";
  const std::size_t at = ("\n" + text).find(prefix);
  if (at == std::string::npos) return std::nan("");
  const std::size_t start = at + prefix.size() - 1;
  double value = 0;
  return absl::SimpleAtod(text.substr(start, text.find('\n', start) - start), &value)
             ? value
             : std::nan("");
}

// Sum and number of the `_count` samples of the stage histogram.
std::pair<double, int> StageCounts(const std::string& text) {
  static const std::regex kCount(
      "\nmeshseg_stage_duration_seconds_count\\{stage=\"[^\"]+\"\\} ([0-9]+)");
  double total = 0;
  int stages = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), kCount), end; it != end; ++it) {
    total += std::stod((*it)[1]);
    ++stages;
  }
  return {total, stages};
}

double StageSecondsSum(const std::string& text) {
  static const std::regex kSum("\nmeshseg_stage_duration_seconds_sum\\{stage=\"[^\"]+\"\\} ([0-9.e+-]+)");
  double total = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), kSum), end; it != end; ++it) {
    total += std::stod((*it)[1]);
  }
  return total;
}

// Runs `command`; returns its exit code and fills *output with stdout+stderr.
int RunCommand(const std::string& command, std::string* output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buffer[512];
  output->clear();
  while (fgets(buffer, sizeof buffer, pipe)) *output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// `promtool check metrics` on `text`: exit code 0 and nothing printed.
void ExpectPromtoolClean(const std::string& text, const std::string& when) {
  const std::string path = testing_files::ScratchPath("scrape_" + when + ".txt");
  std::ofstream(path) << text;
  std::string output;
  const int rc = RunCommand("promtool check metrics < " + path, &output);
  ASSERT_NE(rc, 127) << "promtool not found: bash scripts/setup.sh installs it (Debian prometheus)";
  EXPECT_EQ(rc, 0) << when << ": " << output;
  EXPECT_EQ(output, "") << when;
}

int64_t FileSize(const std::string& path) {
  return static_cast<int64_t>(std::filesystem::file_size(path));
}

TEST(Observability, MetricsMoveWithTheJobsAndJsonLogsParse) {
  const std::string files = FreshDir("files");
  // test_piece at h = 1: a job of about a second, long enough to be seen running.
  const std::string big = files + "/test_piece.ply";
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  ASSERT_TRUE(WriteMesh(part->mesh.tri, big).ok());
  const std::string box = files + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), box);
  const std::string nan = files + "/nan.obj";
  testing_files::WriteText(nan, "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  const std::string step = files + "/part.step";
  testing_files::WriteText(step, "ISO-10303-21;\n");

  ServerProcess server({"--spool-dir", FreshDir("spool"), "--workers", "1", "--metrics-listen",
                        "127.0.0.1:0", "--log-format", "json"});
  ASSERT_FALSE(server.address().empty()) << server.first_line() << server.Log();
  ASSERT_TRUE(server.AwaitLog("\"event\":\"server_started\"", kTimeout)) << server.Log();
  std::smatch match;
  const std::string log_so_far = server.Log();
  ASSERT_TRUE(std::regex_search(
      log_so_far, match, std::regex("\"event\":\"metrics_listening\".*\"address\":\"127\\.0\\.0\\.1:([0-9]+)\"")))
      << log_so_far;
  const int port = std::stoi(match[1]);
  const auto scrape = [&] { return HttpBody(HttpGet(port, "/metrics")); };
  // Scrapes every 10 ms until `done` holds (or kTimeout); returns the last scrape.
  const auto scrape_until = [&](auto done) {
    std::string text = scrape();
    for (const absl::Time end = absl::Now() + kTimeout; !done(text) && absl::Now() < end;) {
      absl::SleepFor(absl::Milliseconds(10));
      text = scrape();
    }
    return text;
  };

  const std::string before = scrape();
  ExpectPromtoolClean(before, "before");
  EXPECT_EQ(Sample(before, "meshseg_jobs_total{state=\"succeeded\"}"), 0) << before;
  EXPECT_EQ(Sample(before, "meshseg_jobs_running"), 0);
  EXPECT_EQ(Sample(before, "meshseg_jobs_queued"), 0);

  MeshsegClient client = MeshsegClient::Connect(server.address());
  const absl::StatusOr<v1::UploadResponse> a = client.Upload(big);
  ASSERT_TRUE(a.ok()) << a.status();
  // A worker counts its attempt just after it marks the job running.
  const std::string during = scrape_until([](const std::string& text) {
    return Sample(text, "meshseg_jobs_running") == 1 &&
           Sample(text, "meshseg_worker_attempts_total") == 1;
  });
  ASSERT_EQ(Sample(during, "meshseg_jobs_running"), 1) << "never saw the job running\n" << during;
  ExpectPromtoolClean(during, "during");
  EXPECT_EQ(Sample(during, "meshseg_jobs_accepted_total"), 1);
  EXPECT_EQ(Sample(during, "meshseg_upload_bytes_total"), FileSize(big));
  EXPECT_EQ(Sample(during, "meshseg_worker_attempts_total"), 1);
  EXPECT_EQ(Sample(during, "meshseg_queue_wait_seconds_count"), 1);
  EXPECT_EQ(Sample(during, "meshseg_jobs_total{state=\"succeeded\"}"), 0);
  EXPECT_EQ(Sample(during, "meshseg_job_duration_seconds_count"), 0);

  // A second job waits behind the first (one worker) and is cancelled there.
  const absl::StatusOr<v1::UploadResponse> b = client.Upload(box);
  ASSERT_TRUE(b.ok()) << b.status();
  const absl::StatusOr<v1::Job> cancelled = client.Cancel(b->job_id());
  ASSERT_TRUE(cancelled.ok()) << cancelled.status();

  const absl::StatusOr<v1::Job> done = client.Watch(a->job_id(), nullptr, kTimeout);
  ASSERT_TRUE(done.ok()) << done.status();
  ASSERT_EQ(done->state(), v1::JOB_STATE_SUCCEEDED) << done->error_message();
  const absl::StatusOr<v1::SegmentationResult> result = client.Result(a->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  const absl::StatusOr<v1::UploadResponse> c = client.Upload(nan);
  ASSERT_TRUE(c.ok()) << c.status();
  const absl::StatusOr<v1::Job> failed = client.Watch(c->job_id(), nullptr, kTimeout);
  ASSERT_TRUE(failed.ok()) << failed.status();
  EXPECT_EQ(failed->state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(client.Upload(step).status().code(), absl::StatusCode::kInvalidArgument);

  // A worker counts a job once the store has it terminal, so a watch may
  // return a moment before the counters move.
  const std::string after = scrape_until([](const std::string& text) {
    return Sample(text, "meshseg_job_duration_seconds_count") == 2;
  });
  ExpectPromtoolClean(after, "after");
  EXPECT_EQ(Sample(after, "meshseg_jobs_total{state=\"succeeded\"}"), 1) << after;
  EXPECT_EQ(Sample(after, "meshseg_jobs_total{state=\"failed\"}"), 1);
  EXPECT_EQ(Sample(after, "meshseg_jobs_total{state=\"cancelled\"}"), 1);
  EXPECT_EQ(Sample(after, "meshseg_jobs_accepted_total"), 3);
  EXPECT_EQ(Sample(after, "meshseg_uploads_rejected_total{code=\"INVALID_ARGUMENT\"}"), 1);
  EXPECT_EQ(Sample(after, "meshseg_upload_bytes_total"),
            FileSize(big) + FileSize(box) + FileSize(nan));
  EXPECT_EQ(Sample(after, "meshseg_result_bytes_total"), result->ByteSizeLong())
      << "the one result written is the one fetched";
  EXPECT_EQ(Sample(after, "meshseg_worker_attempts_total"), 2) << "the cancelled job never ran";
  EXPECT_EQ(Sample(after, "meshseg_queue_wait_seconds_count"), 2);
  EXPECT_EQ(Sample(after, "meshseg_jobs_running"), 0);
  EXPECT_EQ(Sample(after, "meshseg_jobs_queued"), 0);
  const double job_count = Sample(after, "meshseg_job_duration_seconds_count");
  EXPECT_EQ(job_count, 2);
  EXPECT_EQ(Sample(after, "meshseg_job_duration_seconds_bucket{le=\"+Inf\"}"), job_count);
  const double job_seconds = Sample(after, "meshseg_job_duration_seconds_sum");
  EXPECT_GT(job_seconds, 0);
  const auto [stage_observations, stages] = StageCounts(after);
  EXPECT_GE(stages, 3) << "the pipeline reports several stages\n" << after;
  EXPECT_GT(stage_observations, StageCounts(during).first) << "stages ended after the first scrape";
  EXPECT_LE(StageSecondsSum(after), job_seconds) << "stages happen inside their jobs' run time";
  EXPECT_EQ(Sample(after, "meshseg_admission_reserved_bytes"), 0) << "no admission control yet (#30)";

  server.Signal(SIGTERM);
  ASSERT_EQ(server.AwaitExit(kTimeout), 0);
  const std::string log_path = testing_files::ScratchPath("server_log.jsonl");
  std::ofstream(log_path) << server.Log();
  std::string output;
  const int rc = RunCommand(absl::StrCat("python3 ", MESHSEG_TESTS_DIR, "/server/check_json_log.py ",
                                  log_path,
                                  " server_started metrics_listening job_queued job_started"
                                  " stage_done job_finished job_cancel_requested upload_rejected"
                                  " shutdown_done"),
                     &output);
  EXPECT_EQ(rc, 0) << output << "\n" << server.Log();
  EXPECT_THAT(server.Log(), HasSubstr(absl::StrCat("\"event\":\"job_finished\",\"job_id\":\"",
                                                   a->job_id(), "\"")));
}

}  // namespace
}  // namespace meshseg
