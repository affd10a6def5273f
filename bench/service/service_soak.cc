// Load and soak test of a running meshseg server (issue 34), driven by
// bench/service/load, which starts the server on loopback. --clients threads
// submit jobs back to back for --seconds, a mix of
//   - good files: small and medium generated parts, PLY and OFF;
//     every result must equal the offline result of the same file (face
//     labels, region count and surface types), computed here first with the
//     same pipeline the CLI runs;
//   - cancels: a good file cancelled a random 0-400 ms after upload; the job
//     must end CANCELLED, or SUCCEEDED with the offline result if it was
//     already done;
//   - bad files (a truncated OFF, a NaN coordinate, bytes of no format, an
//     empty file): the upload or the job must fail with a message.
// A job whose upload was accepted but whose end is never seen (watch error,
// deadline, NOT_FOUND) is LOST. The server's RSS (/proc/PID/status) is read
// every second; growth is the last minute of load against the first minute
// after --warmup_seconds.
// Prints submitted / completed / failed / cancelled / lost / mismatched,
// p50 / p95 latency of good jobs and the RSS samples; exit 1 if any job was
// lost or mismatched.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "absl/flags/flag.h"
#include "absl/flags/parse.h"
#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/proto/convert.h"

ABSL_FLAG(std::string, server, "127.0.0.1:50051", "the server's address (loopback)");
ABSL_FLAG(int, server_pid, 0, "its process id, for RSS samples (0 = none)");
ABSL_FLAG(int, clients, 16, "concurrent clients");
ABSL_FLAG(double, seconds, 600, "how long new jobs are submitted");
ABSL_FLAG(double, warmup_seconds, 60, "RSS growth is measured from this point on");
ABSL_FLAG(std::string, work_dir, "/tmp", "where the test files are written");
ABSL_FLAG(int, seed, 1, "random seed of the job mix");

namespace meshseg {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Resident set size of `pid` in KiB, from /proc/PID/status (0 if unknown).
int64_t RssKiB(int pid) {
  if (pid <= 0) return 0;
  std::ifstream in(absl::StrCat("/proc/", pid, "/status"));
  std::string key;
  while (in >> key) {
    if (key == "VmRSS:") {
      int64_t kib = 0;
      in >> kib;
      return kib;
    }
    in.ignore(1 << 20, '\n');
  }
  return 0;
}

// A file every good job segments, with its offline result.
struct GoodFile {
  std::string path;
  v1::SegmentationResult expected;
};

// The offline result must match the server's: same labels per face, same
// regions with the same surface types (parameters are compared by the
// pipeline tests; here any difference in labels would show a mix-up).
bool SameResult(const v1::SegmentationResult& a, const v1::SegmentationResult& b) {
  if (a.face_labels_size() != b.face_labels_size() || a.regions_size() != b.regions_size()) {
    return false;
  }
  for (int i = 0; i < a.face_labels_size(); ++i) {
    if (a.face_labels(i) != b.face_labels(i)) return false;
  }
  for (int r = 0; r < a.regions_size(); ++r) {
    if (a.regions(r).surface_case() != b.regions(r).surface_case()) return false;
  }
  return true;
}

absl::StatusOr<GoodFile> MakeGoodFile(const std::string& part, double voxel,
                                      const std::string& path) {
  absl::StatusOr<GeneratedPart> generated = GeneratePart(part, {.voxel_size = voxel});
  if (!generated.ok()) return generated.status();
  if (absl::Status s = WriteMesh(generated->mesh.tri, path); !s.ok()) return s;
  absl::StatusOr<PipelineResult> offline = RunPipeline(path);
  if (!offline.ok()) return offline.status();
  return GoodFile{path, ToProto(*offline)};
}

// Files the server must refuse, each with a message.
std::vector<std::string> MakeBadFiles(const std::string& dir, const std::string& good_off) {
  std::vector<std::string> paths;
  const auto write = [&](const std::string& name, const std::string& bytes) {
    const std::string path = absl::StrCat(dir, "/", name);
    std::ofstream(path, std::ios::binary) << bytes;
    paths.push_back(path);
  };
  std::ifstream in(good_off, std::ios::binary);
  const std::string off((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write("truncated.off", off.substr(0, off.size() / 2 + 7));
  write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  write("noise.ply", std::string(4096, '\x9c'));
  write("empty.obj", "");
  return paths;
}

struct Counts {
  int64_t submitted = 0, completed = 0, failed = 0, refused = 0, cancelled = 0;
  int64_t lost = 0, mismatched = 0;
  std::vector<double> latencies;
  std::vector<std::string> problems;  // first few lost / mismatched jobs
};

class Soak {
 public:
  Soak(std::vector<GoodFile> good, std::vector<std::string> bad)
      : good_(std::move(good)), bad_(std::move(bad)) {}

  // One client's loop until `deadline`.
  void RunClient(int index, Clock::time_point deadline) {
    MeshsegClient client = MeshsegClient::Connect(absl::GetFlag(FLAGS_server));
    std::mt19937 rng(absl::GetFlag(FLAGS_seed) * 1000 + index);
    while (Clock::now() < deadline) {
      const int kind = std::uniform_int_distribution<int>(0, 9)(rng);  // 7 good, 2 cancel, 1 bad
      if (kind == 9) {
        BadJob(client, bad_[std::uniform_int_distribution<size_t>(0, bad_.size() - 1)(rng)]);
      } else {
        const GoodFile& file = good_[std::uniform_int_distribution<size_t>(0, good_.size() - 1)(rng)];
        const int cancel_ms = kind >= 7 ? std::uniform_int_distribution<int>(0, 400)(rng) : -1;
        GoodJob(client, file, cancel_ms);
      }
    }
  }

  Counts counts() {
    absl::MutexLock lock(&mu_);
    return counts_;
  }

 private:
  void Problem(Counts& c, std::string what) {
    if (c.problems.size() < 10) c.problems.push_back(std::move(what));
  }

  void GoodJob(MeshsegClient& client, const GoodFile& file, int cancel_ms) {
    const Clock::time_point start = Clock::now();
    const absl::StatusOr<v1::UploadResponse> upload = client.Upload(file.path);
    absl::StatusOr<v1::Job> job = absl::UnknownError("not watched");
    absl::StatusOr<v1::SegmentationResult> result = absl::UnknownError("not fetched");
    if (upload.ok()) {
      if (cancel_ms >= 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(cancel_ms));
        (void)client.Cancel(upload->job_id());  // may race with the job's end; checked below
      }
      job = client.Watch(upload->job_id(), {}, absl::Minutes(10));
      if (job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) result = client.Result(job->job_id());
    }
    const double seconds = SecondsSince(start);
    absl::MutexLock lock(&mu_);
    ++counts_.submitted;
    if (!upload.ok()) {
      // Not accepted, so not lost; a full queue is the one expected reason.
      ++counts_.refused;
      if (upload.status().code() != absl::StatusCode::kResourceExhausted) {
        Problem(counts_, absl::StrCat(file.path, ": upload ", upload.status().ToString()));
      }
      return;
    }
    const std::string& id = upload->job_id();
    if (!job.ok()) {
      ++counts_.lost;
      Problem(counts_, absl::StrCat(id, ": watch ", job.status().ToString()));
    } else if (job->state() == v1::JOB_STATE_CANCELLED && cancel_ms >= 0) {
      ++counts_.cancelled;
    } else if (job->state() != v1::JOB_STATE_SUCCEEDED) {
      ++counts_.lost;
      Problem(counts_, absl::StrCat(id, ": ended ", v1::JobState_Name(job->state()), " ",
                                    job->error_message()));
    } else if (!result.ok()) {
      ++counts_.lost;
      Problem(counts_, absl::StrCat(id, ": result ", result.status().ToString()));
    } else if (!SameResult(*result, file.expected)) {
      ++counts_.mismatched;
      Problem(counts_, absl::StrCat(id, ": result differs from the offline result of ", file.path));
    } else {
      ++counts_.completed;
      if (cancel_ms < 0) counts_.latencies.push_back(seconds);
    }
  }

  void BadJob(MeshsegClient& client, const std::string& path) {
    const absl::StatusOr<v1::UploadResponse> upload = client.Upload(path);
    absl::StatusOr<v1::Job> job = absl::UnknownError("refused at upload");
    if (upload.ok()) job = client.Watch(upload->job_id(), {}, absl::Minutes(10));
    absl::MutexLock lock(&mu_);
    ++counts_.submitted;
    if (!upload.ok()) {
      // Refused with a message naming the problem: the expected outcome.
      if (upload.status().message().empty()) Problem(counts_, path + ": refused without a message");
      ++counts_.failed;
    } else if (!job.ok()) {
      ++counts_.lost;
      Problem(counts_, absl::StrCat(upload->job_id(), ": watch ", job.status().ToString()));
    } else if (job->state() == v1::JOB_STATE_FAILED && !job->error_message().empty()) {
      ++counts_.failed;
    } else {
      ++counts_.mismatched;  // a bad file must not succeed
      Problem(counts_, absl::StrCat(path, ": ended ", v1::JobState_Name(job->state())));
    }
  }

  const std::vector<GoodFile> good_;
  const std::vector<std::string> bad_;
  absl::Mutex mu_;
  Counts counts_ ABSL_GUARDED_BY(mu_);
};

int Run() {
  const std::string dir = absl::GetFlag(FLAGS_work_dir);
  const int pid = absl::GetFlag(FLAGS_server_pid);
  const int64_t rss_start = RssKiB(pid);
  std::vector<GoodFile> good;
  // Small (~19 K faces) and medium (~70 K faces) parts, PLY and OFF.
  for (const auto& [part, voxel, ext] :
       std::vector<std::tuple<std::string, double, std::string>>{
           {"small_block", 0.0, "ply"}, {"small_block", 0.0, "off"}, {"test_piece", 0.8, "ply"}}) {
    absl::StatusOr<GoodFile> file =
        MakeGoodFile(part, voxel, absl::StrCat(dir, "/", part, "_", voxel, ".", ext));
    if (!file.ok()) {
      std::fprintf(stderr, "service_soak: %s\n", file.status().ToString().c_str());
      return 1;
    }
    good.push_back(*std::move(file));
  }
  Soak soak(good, MakeBadFiles(dir, good[1].path));

  const Clock::time_point start = Clock::now();
  const Clock::time_point deadline =
      start + std::chrono::milliseconds(static_cast<int64_t>(1e3 * absl::GetFlag(FLAGS_seconds)));
  std::vector<std::thread> threads;
  for (int c = 0; c < absl::GetFlag(FLAGS_clients); ++c) {
    threads.emplace_back([&soak, c, deadline] { soak.RunClient(c, deadline); });
  }
  // RSS sampled every second while jobs run. A single sample depends on how
  // many jobs happen to be in flight, so growth compares the mean RSS of the
  // first minute after warm-up with the mean of the last minute of load.
  std::vector<std::pair<double, int64_t>> samples;  // (seconds since start, KiB)
  std::atomic<bool> done{false};
  std::thread sampler([&] {
    while (!done) {
      std::this_thread::sleep_for(std::chrono::seconds(1));
      samples.emplace_back(SecondsSince(start), RssKiB(pid));
    }
  });
  for (std::thread& t : threads) t.join();
  done = true;
  sampler.join();
  const int64_t rss_end = RssKiB(pid);
  const double wall = SecondsSince(start);

  Counts c = soak.counts();
  std::sort(c.latencies.begin(), c.latencies.end());
  const auto at = [&](double q) {
    if (c.latencies.empty()) return 0.0;
    return c.latencies[std::min(c.latencies.size() - 1,
                                static_cast<size_t>(q * static_cast<double>(c.latencies.size())))];
  };
  std::printf(
      "clients=%d wall=%.0f s submitted=%lld completed=%lld failed=%lld refused=%lld "
      "cancelled=%lld lost=%lld mismatched=%lld\n",
      absl::GetFlag(FLAGS_clients), wall, static_cast<long long>(c.submitted),
      static_cast<long long>(c.completed), static_cast<long long>(c.failed),
      static_cast<long long>(c.refused), static_cast<long long>(c.cancelled),
      static_cast<long long>(c.lost), static_cast<long long>(c.mismatched));
  std::printf("latency of good jobs: p50=%.2f s p95=%.2f s\n", at(0.5), at(0.95));
  if (pid > 0 && !samples.empty()) {
    const double warmup = absl::GetFlag(FLAGS_warmup_seconds);
    const double load_end = absl::GetFlag(FLAGS_seconds);
    const auto mean_mib = [&](double from, double to) {
      double sum = 0;
      int n = 0;
      for (const auto& [t, kib] : samples) {
        if (t >= from && t < to) sum += kib, ++n;
      }
      return n > 0 ? sum / n / 1024.0 : 0.0;
    };
    int64_t peak = rss_start;
    for (const auto& [t, kib] : samples) peak = std::max(peak, kib);
    std::printf("server RSS (MiB, mean per minute):");
    for (double m = 0; m < load_end; m += 60) std::printf(" %.0f", mean_mib(m, m + 60));
    const double first = mean_mib(warmup, warmup + 60);
    const double last = mean_mib(load_end - 60, load_end);
    std::printf("\nserver RSS: start %.1f MiB, peak %.1f MiB, idle at the end %.1f MiB; ",
                rss_start / 1024.0, peak / 1024.0, rss_end / 1024.0);
    std::printf("first minute after warm-up %.1f MiB, last minute %.1f MiB: growth %+.1f %%\n",
                first, last, first > 0 ? 100.0 * (last - first) / first : 0.0);
  }
  for (const std::string& p : c.problems) std::printf("  problem: %s\n", p.c_str());
  return c.lost == 0 && c.mismatched == 0 ? 0 : 1;
}

}  // namespace
}  // namespace meshseg

int main(int argc, char** argv) {
  absl::ParseCommandLine(argc, argv);
  return meshseg::Run();
}
