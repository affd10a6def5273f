// Admission control on a real loopback server: a job whose estimated peak
// memory (EstimateJobMemory) exceeds the whole --memory-budget is refused at
// upload with the numbers; jobs that fit only one at a time run one at a
// time (the process's peak RSS measured); free disk is reserved before an
// upload's data is received; the streaming-call cap refuses the call after
// the last slot. Plus the parts alone: MemoryBudget, DiskReservations,
// ParseByteSize.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "client/meshseg_client.h"
#include "meshseg/pipeline.h"
#include "server/disk_reservations.h"
#include "server/memory_budget.h"
#include "server/server_options.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

// Peak resident memory of this process (VmHWM), in bytes.
int64_t PeakRss() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
  }
  return -1;
}

// Resets VmHWM to the current RSS (Linux >= 4.0).
void ResetPeakRss() { std::ofstream("/proc/self/clear_refs") << "5"; }

std::string BoxFile(int n) {
  const std::string path = FreshDir("mesh") + "/box.stl";
  testing_files::WriteStlBinary(testing_files::SplitBox(n, {1, 1, 1}), path);
  return path;
}

int64_t Estimate(const std::string& path) {
  const absl::StatusOr<MemoryEstimate> e = EstimateJobMemory(path);
  EXPECT_TRUE(e.ok()) << e.status();
  return e.ok() ? e->peak_bytes : 0;
}

// Counts runners inside RunPipeline at once; each waits up to `hold` for a
// second one to come in (so overlap is seen when the budget allows it).
struct Concurrency {
  std::atomic<int> active{0};
  std::atomic<int> most{0};
  absl::Duration hold = absl::ZeroDuration();

  JobRunner Runner() {
    return [this](const std::string& path, const PipelineParams& params, const RunContext& ctx) {
      const int now = ++active;
      int seen = most.load();
      while (now > seen && !most.compare_exchange_weak(seen, now)) {
      }
      const absl::Time until = absl::Now() + hold;
      while (most < 2 && absl::Now() < until) absl::SleepFor(absl::Milliseconds(5));
      absl::StatusOr<PipelineResult> result = RunPipeline(path, params, ctx);
      --active;
      return result;
    };
  }
};

// Uploads `path` `n` times from `n` threads, then waits for every job;
// returns their final states.
std::vector<v1::JobState> RunConcurrently(TestServer& server, const std::string& path, int n) {
  std::vector<v1::JobState> states(n, v1::JOB_STATE_UNSPECIFIED);
  std::vector<std::thread> threads;
  for (int i = 0; i < n; ++i) {
    threads.emplace_back([&, i] {
      MeshsegClient client = server.Client();
      client.set_call_timeout(absl::Seconds(60));
      absl::StatusOr<v1::UploadResponse> up = client.Upload(path);
      if (!up.ok()) return;
      absl::StatusOr<v1::Job> job = client.Watch(up->job_id(), {}, absl::Seconds(120));
      if (job.ok()) states[i] = job->state();
    });
  }
  for (std::thread& t : threads) t.join();
  return states;
}

TEST(Admission, AJobOverTheWholeBudgetIsRefusedAtUploadWithTheNumbers) {
  const std::string path = BoxFile(4);
  const int64_t estimate = Estimate(path);
  ServerOptions options;
  options.memory_budget = estimate / 2;
  TestServer server(std::move(options));
  MeshsegClient client = server.Client();
  const absl::StatusOr<v1::UploadResponse> up = client.Upload(path);
  EXPECT_EQ(up.status().code(), absl::StatusCode::kResourceExhausted) << up.status();
  EXPECT_THAT(up.status().message(), HasSubstr("192 faces"));
  EXPECT_THAT(up.status().message(), HasSubstr(absl::StrCat("(", estimate, " bytes)")));
  EXPECT_THAT(up.status().message(),
              HasSubstr(absl::StrCat("(", estimate / 2, " bytes, --memory-budget)")));
  EXPECT_THAT(*client.ListJobs(), ::testing::IsEmpty());
  EXPECT_EQ(server.SpoolFiles(), 0);
}

// Four concurrent uploads of a mesh on two workers, under a budget that
// holds 1.5 of its estimated peaks: they run one at a time, all succeed,
// and the process's peak RSS grows by less than the budget.
TEST(Admission, FourLargeUploadsUnderASmallBudgetRunOneAtATime) {
  const std::string path = BoxFile(40);  // 19 200 faces
  const int64_t estimate = Estimate(path);
  Concurrency concurrency{.hold = absl::Milliseconds(300)};
  ServerOptions options;
  options.workers = 2;
  options.memory_budget = estimate * 3 / 2;
  options.runner = concurrency.Runner();
  TestServer server(std::move(options));
  ResetPeakRss();
  const int64_t before = PeakRss();
  const std::vector<v1::JobState> states = RunConcurrently(server, path, 4);
  const int64_t growth = PeakRss() - before;
  EXPECT_THAT(states, ::testing::Each(v1::JOB_STATE_SUCCEEDED));
  EXPECT_EQ(concurrency.most, 1);
  EXPECT_LT(growth, options.memory_budget) << "estimate " << estimate;
  std::printf("estimate %lld bytes, budget %lld, peak RSS growth %lld bytes\n",
              static_cast<long long>(estimate), static_cast<long long>(estimate * 3 / 2),
              static_cast<long long>(growth));
}

// The same with room for two: the budget, not the worker count, was the
// limit above.
TEST(Admission, JobsThatFitTogetherRunTogether) {
  const std::string path = BoxFile(2);
  const int64_t estimate = Estimate(path);
  Concurrency concurrency{.hold = absl::Seconds(5)};
  ServerOptions options;
  options.workers = 2;
  options.memory_budget = estimate * 5 / 2;
  options.runner = concurrency.Runner();
  TestServer server(std::move(options));
  EXPECT_THAT(RunConcurrently(server, path, 2), ::testing::Each(v1::JOB_STATE_SUCCEEDED));
  EXPECT_EQ(concurrency.most, 2);
}

TEST(Admission, AnUploadThatWouldFillTheDiskIsRefusedBeforeItsData) {
  ServerOptions options;
  options.min_free_disk = int64_t{1} << 60;  // more than any disk has
  TestServer server(std::move(options));
  MeshsegClient client = server.Client();
  const absl::StatusOr<v1::UploadResponse> up = client.Upload(BoxFile(2));
  EXPECT_EQ(up.status().code(), absl::StatusCode::kResourceExhausted) << up.status();
  EXPECT_THAT(up.status().message(), HasSubstr("--min-free-disk"));
  EXPECT_EQ(server.SpoolFiles(), 0);
}

TEST(Admission, StreamingCallsBeyondTheCapAreRefusedAndSlotsComeBack) {
  Gate gate;
  ServerOptions options;
  options.workers = 1;
  options.max_concurrent_streams = 2;
  options.runner = gate.Runner();
  TestServer server(std::move(options));
  const std::string path = BoxFile(2);
  MeshsegClient client = server.Client();
  const absl::StatusOr<v1::UploadResponse> up = client.Upload(path);
  ASSERT_TRUE(up.ok()) << up.status();
  std::vector<absl::StatusOr<v1::Job>> watched(2, absl::UnknownError("not run"));
  std::atomic<int> first_events{0};
  std::vector<std::thread> watchers;
  for (int i = 0; i < 2; ++i) {
    watchers.emplace_back([&, i] {
      MeshsegClient c = server.Client();
      bool counted = false;
      watched[i] = c.Watch(
          up->job_id(),
          [&](const v1::JobEvent&) {
            if (!counted) ++first_events;
            counted = true;
          },
          absl::Seconds(30));
    });
  }
  // A watcher's first event is sent after it took its slot: once both have
  // one, a third stream is refused.
  ASSERT_TRUE(Eventually([&] { return first_events == 2; }));
  const absl::Status third = client.Watch(up->job_id(), {}, absl::Seconds(5)).status();
  EXPECT_EQ(third.code(), absl::StatusCode::kResourceExhausted) << third;
  EXPECT_THAT(third.message(), HasSubstr("--max-concurrent-streams 2"));
  EXPECT_EQ(client.Upload(path).status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_TRUE(client.GetJob(up->job_id()).ok());  // unary calls are not capped

  gate.open.Notify();
  for (std::thread& t : watchers) t.join();
  for (const auto& job : watched) {
    ASSERT_TRUE(job.ok()) << job.status();
    EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED);
  }
  EXPECT_EQ(client.Watch(up->job_id())->state(), v1::JOB_STATE_SUCCEEDED);
}

TEST(MemoryBudget, GrantsInRequestOrderAndStopsAWaiter) {
  MemoryBudget budget(100);
  std::stop_source never;
  ASSERT_TRUE(budget.Reserve(60, never.get_token()));
  std::vector<int> order;
  absl::Mutex mu;
  std::thread big([&] {
    EXPECT_TRUE(budget.Reserve(80, never.get_token()));
    absl::MutexLock lock(&mu);
    order.push_back(80);
  });
  ASSERT_TRUE(Eventually([&] { return budget.waiting() == 1; }));
  // 30 would fit next to 60, but the 80 asked first: it waits its turn.
  std::thread small([&] {
    EXPECT_TRUE(budget.Reserve(30, never.get_token()));
    absl::MutexLock lock(&mu);
    order.push_back(30);
  });
  ASSERT_TRUE(Eventually([&] { return budget.waiting() == 2; }));
  budget.Release(60);
  big.join();
  EXPECT_EQ(budget.waiting(), 1);  // 80 + 30 > 100
  budget.Release(80);
  small.join();
  EXPECT_EQ(order, (std::vector<int>{80, 30}));
  EXPECT_EQ(budget.peak_reserved(), 80);

  std::stop_source stop;
  std::thread stopped([&] { EXPECT_FALSE(budget.Reserve(90, stop.get_token())); });
  ASSERT_TRUE(Eventually([&] { return budget.waiting() == 1; }));
  stop.request_stop();
  stopped.join();
  EXPECT_EQ(budget.reserved(), 30);
}

TEST(DiskReservations, CountsUploadsInFlightAgainstTheFreeSpace) {
  int64_t free = 1000;
  DiskReservations disk({FreshDir("a")}, 100, [&](const std::string&) { return free; });
  absl::StatusOr<std::unique_ptr<DiskReservations::Hold>> a = disk.Reserve(500);
  ASSERT_TRUE(a.ok());
  const auto b = disk.Reserve(401);  // 1000 - 500 - 401 < 100
  EXPECT_EQ(b.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(b.status().message(), HasSubstr("1000 bytes free, 500 reserved"));
  EXPECT_TRUE(disk.Reserve(400).ok());  // released at once (the Hold is dropped)
  a->reset();
  EXPECT_EQ(disk.reserved(), 0);
  EXPECT_TRUE(disk.Reserve(900).ok());
  // Two folders on one filesystem are counted once.
  const std::string dir = FreshDir("b");
  std::filesystem::create_directories(dir + "/x");
  int calls = 0;
  DiskReservations same({dir, dir + "/x"}, 0, [&](const std::string&) {
    ++calls;
    return int64_t{1} << 40;
  });
  EXPECT_TRUE(same.Reserve(1).ok());
  EXPECT_EQ(calls, 1);
}

TEST(ParseByteSize, ReadsSuffixesAndRefusesTheRest) {
  EXPECT_EQ(*ParseByteSize("6Gi", "--memory-budget"), int64_t{6} << 30);
  EXPECT_EQ(*ParseByteSize("512Mi", "--x"), int64_t{512} << 20);
  EXPECT_EQ(*ParseByteSize("2G", "--x"), 2'000'000'000);
  EXPECT_EQ(*ParseByteSize("123", "--x"), 123);
  EXPECT_EQ(*ParseByteSize("0", "--x"), 0);
  for (const char* bad : {"", "-1", "6GB", "1.5Gi", "Gi", "99999999999Ti"}) {
    const absl::StatusOr<int64_t> v = ParseByteSize(bad, "--memory-budget");
    EXPECT_EQ(v.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(v.status().message(), HasSubstr("--memory-budget")) << bad;
  }
}

}  // namespace
}  // namespace meshseg::server
