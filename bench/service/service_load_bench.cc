// Load on running meshseg servers (issue 29: embedded vs Redis mode): jobs
// per second and per-job latency of one generated part, from --clients
// threads spread over --servers (api replicas), each running --jobs jobs
// through MeshsegClient::Segment (upload, watch, fetch). The servers are
// started by bench/service/scale_out.sh, which runs this tool for each setup.
// Usage:
//   build/bin/service_load_bench --servers=127.0.0.1:50051[,HOST:PORT...]
//       [--clients=1] [--jobs=20] [--part=small_block] [--voxel=0] [--label=TEXT]
// Prints one line: label, jobs, wall seconds, jobs/s, mean / p50 / p95 job
// latency in ms. Every job must succeed with one label per input face, else
// one line on stderr and exit 1.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "absl/flags/flag.h"
#include "absl/flags/parse.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/synchronization/mutex.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"

ABSL_FLAG(std::string, servers, "127.0.0.1:50051", "comma-separated api addresses");
ABSL_FLAG(int, clients, 1, "concurrent clients (client c uses server c % N)");
ABSL_FLAG(int, jobs, 20, "jobs per client");
ABSL_FLAG(std::string, part, "small_block", "generated part every job segments");
ABSL_FLAG(double, voxel, 0.0, "its voxel size (0 = the part's default)");
ABSL_FLAG(std::string, label, "", "first column of the output line");
ABSL_FLAG(std::string, work_dir, "/tmp", "where the part file is written");

namespace meshseg {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int Run() {
  const std::vector<std::string> servers =
      absl::StrSplit(absl::GetFlag(FLAGS_servers), ',', absl::SkipEmpty());
  const int clients = absl::GetFlag(FLAGS_clients);
  const int jobs = absl::GetFlag(FLAGS_jobs);
  if (servers.empty() || clients < 1 || jobs < 1) {
    std::fprintf(stderr, "service_load_bench: need --servers, --clients >= 1, --jobs >= 1\n");
    return 1;
  }
  const absl::StatusOr<GeneratedPart> part =
      GeneratePart(absl::GetFlag(FLAGS_part), {.voxel_size = absl::GetFlag(FLAGS_voxel)});
  if (!part.ok()) {
    std::fprintf(stderr, "service_load_bench: %s\n", part.status().ToString().c_str());
    return 1;
  }
  const int64_t faces = static_cast<int64_t>(part->mesh.tri.n_faces());
  const std::string path =
      absl::StrCat(absl::GetFlag(FLAGS_work_dir), "/load_", getpid(), "_", part->name, ".ply");
  if (absl::Status s = WriteMesh(part->mesh.tri, path); !s.ok()) {
    std::fprintf(stderr, "service_load_bench: %s\n", s.ToString().c_str());
    return 1;
  }

  absl::Mutex mu;
  std::string error;
  std::vector<double> latencies;
  const Clock::time_point start = Clock::now();
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&, c] {
      MeshsegClient client = MeshsegClient::Connect(servers[c % servers.size()]);
      for (int j = 0; j < jobs; ++j) {
        const Clock::time_point job_start = Clock::now();
        const absl::StatusOr<v1::SegmentationResult> result = client.Segment(path);
        const double seconds = SecondsSince(job_start);
        absl::MutexLock lock(&mu);
        if (!result.ok() || result->face_labels_size() != faces) {
          if (error.empty()) {
            error = result.ok() ? "wrong number of face labels" : result.status().ToString();
          }
          return;
        }
        latencies.push_back(seconds);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  const double wall = SecondsSince(start);
  std::filesystem::remove(path);
  if (!error.empty()) {
    std::fprintf(stderr, "service_load_bench: %s\n", error.c_str());
    return 1;
  }
  std::sort(latencies.begin(), latencies.end());
  double sum = 0;
  for (double l : latencies) sum += l;
  const auto at = [&](double q) {
    return latencies[std::min(latencies.size() - 1,
                              static_cast<std::size_t>(q * static_cast<double>(latencies.size())))];
  };
  std::printf(
      "%-28s jobs=%-4zu faces=%-7lld wall=%7.2f s  %7.2f jobs/s  mean=%7.1f ms  "
      "p50=%7.1f ms  p95=%7.1f ms\n",
      absl::GetFlag(FLAGS_label).c_str(), latencies.size(), static_cast<long long>(faces), wall,
      latencies.size() / wall, 1e3 * sum / latencies.size(), 1e3 * at(0.5), 1e3 * at(0.95));
  return 0;
}

}  // namespace
}  // namespace meshseg

int main(int argc, char** argv) {
  absl::ParseCommandLine(argc, argv);
  return meshseg::Run();
}
