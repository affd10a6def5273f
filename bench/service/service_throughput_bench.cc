// Throughput of the meshseg gRPC service over loopback (issue 4): jobs per
// second for small parts and upload MB/s for a large one.
// Usage:
//   build/bin/service_throughput_bench [--clients=4] [--jobs=10]
//       [--small_part=small_block] [--large_part=test_piece] [--large_voxel=0.21]
//       [--uploads=3] [--large_e2e=true] 2>/dev/null
// (the server's structured log goes to stderr; the numbers go to stdout).
// Starts a real meshseg server in-process on 127.0.0.1:0 (workers = cores, a
// temp spool folder removed at the end), then:
//   1. small: each of --clients threads runs --jobs jobs of the small part
//      through MeshsegClient::Segment (upload, watch, fetch the result); prints
//      jobs/s and the mean and p95 latency of one job.
//   2. large: --uploads timed uploads of the large part, with and without the
//      SHA-256 the client computes and the server checks; each job is cancelled
//      at once so it does not compete for the cores. Prints MB/s (1 MB = 1e6
//      bytes). With --large_e2e, one more job of it is run end to end.
// Every job must succeed with one label per input face; otherwise the tool
// prints one line on stderr and exits 1. Parts are written as binary PLY.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/flags/flag.h"
#include "absl/flags/parse.h"
#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/status_macros.h"
#include "server/server.h"

ABSL_FLAG(int, clients, 4, "concurrent clients for the small-part jobs");
ABSL_FLAG(int, jobs, 10, "small-part jobs per client");
ABSL_FLAG(std::string, small_part, "small_block", "generated part for the jobs/s run");
ABSL_FLAG(std::string, large_part, "test_piece", "generated part for the upload run");
ABSL_FLAG(double, large_voxel, 0.21, "voxel size of the large part (0.21: ~1M faces)");
ABSL_FLAG(int, uploads, 3, "timed uploads of the large part, per checksum setting");
ABSL_FLAG(bool, large_e2e, true, "also run one large-part job end to end");

namespace meshseg {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A generated part written to a file, and the face count its result must have.
struct PartFile {
  std::string path;
  int64_t faces = 0;
  int64_t bytes = 0;
};

absl::StatusOr<PartFile> WritePart(const std::string& name, double voxel_size,
                                   const std::string& dir) {
  const Clock::time_point start = Clock::now();
  MESHSEG_ASSIGN_OR_RETURN(const GeneratedPart part, GeneratePart(name, {.voxel_size = voxel_size}));
  PartFile file{.path = absl::StrCat(dir, "/", name, ".ply"),
                .faces = static_cast<int64_t>(part.mesh.tri.n_faces())};
  MESHSEG_RETURN_IF_ERROR(WriteMesh(part.mesh.tri, file.path));
  file.bytes = static_cast<int64_t>(std::filesystem::file_size(file.path));
  std::printf("part %-12s h=%.3g  %lld faces  %.2f MB  (generated in %.1f s)\n", name.c_str(),
              part.voxel_size, static_cast<long long>(file.faces), file.bytes / 1e6,
              SecondsSince(start));
  return file;
}

// A job must have succeeded (Segment checks) and labelled every input face.
absl::Status CheckResult(const v1::SegmentationResult& result, const PartFile& part) {
  if (result.face_labels_size() != part.faces || result.mesh().face_count() != part.faces ||
      result.regions_size() == 0) {
    return absl::InternalError(absl::StrCat("\"", part.path, "\": result has ",
                                            result.face_labels_size(), " labels and ",
                                            result.regions_size(), " regions for ", part.faces,
                                            " faces"));
  }
  return absl::OkStatus();
}

// 1. jobs/s: `clients` threads, each with its own channel, run `jobs` jobs.
absl::Status SmallJobs(const std::string& address, const PartFile& part, int clients, int jobs) {
  absl::Mutex mu;
  absl::Status first_error;
  std::vector<double> latencies;  // seconds, guarded by mu
  const Clock::time_point start = Clock::now();
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&] {
      MeshsegClient client = MeshsegClient::Connect(address);
      for (int j = 0; j < jobs; ++j) {
        const Clock::time_point job_start = Clock::now();
        absl::StatusOr<v1::SegmentationResult> result = client.Segment(part.path);
        const double seconds = SecondsSince(job_start);
        const absl::Status status = result.ok() ? CheckResult(*result, part) : result.status();
        absl::MutexLock lock(&mu);
        if (!status.ok()) {
          if (first_error.ok()) first_error = status;
          return;
        }
        latencies.push_back(seconds);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  const double wall = SecondsSince(start);
  MESHSEG_RETURN_IF_ERROR(first_error);

  std::sort(latencies.begin(), latencies.end());
  double sum = 0.0;
  for (double s : latencies) sum += s;
  const size_t n = latencies.size();
  const double p95 = latencies[static_cast<size_t>(std::ceil(0.95 * n)) - 1];
  std::printf("small: %d clients x %d jobs = %zu jobs in %.2f s: %.2f jobs/s; "
              "latency mean %.0f ms, p95 %.0f ms, max %.0f ms\n",
              clients, jobs, n, wall, n / wall, 1e3 * sum / n, 1e3 * p95, 1e3 * latencies.back());
  return absl::OkStatus();
}

// Uploads `part`, timing the Upload call until the job id comes back; then
// cancels the job and waits for it to end.
absl::StatusOr<double> TimedUpload(MeshsegClient& client, const PartFile& part, bool checksum) {
  UploadOptions options;
  options.checksum = checksum;
  const Clock::time_point start = Clock::now();
  MESHSEG_ASSIGN_OR_RETURN(const v1::UploadResponse upload, client.Upload(part.path, options));
  const double seconds = SecondsSince(start);
  // CANCELLED or, if it already finished, any terminal state is fine here.
  MESHSEG_RETURN_IF_ERROR(client.Cancel(upload.job_id()).status());
  MESHSEG_RETURN_IF_ERROR(client.Watch(upload.job_id()).status());
  return seconds;
}

// 2. upload MB/s of the large part, then optionally one job end to end.
absl::Status LargeUpload(const std::string& address, const PartFile& part, int uploads,
                         bool e2e) {
  MeshsegClient client = MeshsegClient::Connect(address);
  for (const bool checksum : {true, false}) {
    double best = 1e300, sum = 0.0;
    for (int i = 0; i < uploads; ++i) {
      MESHSEG_ASSIGN_OR_RETURN(const double s, TimedUpload(client, part, checksum));
      best = std::min(best, s);
      sum += s;
    }
    std::printf("large upload (%-11s): %.2f MB x %d: mean %.3f s = %.0f MB/s, best %.0f MB/s\n",
                checksum ? "sha256" : "no checksum", part.bytes / 1e6, uploads, sum / uploads,
                part.bytes / 1e6 / (sum / uploads), part.bytes / 1e6 / best);
  }
  if (!e2e) return absl::OkStatus();
  const Clock::time_point start = Clock::now();
  MESHSEG_ASSIGN_OR_RETURN(const v1::SegmentationResult result, client.Segment(part.path));
  MESHSEG_RETURN_IF_ERROR(CheckResult(result, part));
  std::printf("large job end to end (upload, segment, fetch): %.2f s, %d regions\n",
              SecondsSince(start), result.regions_size());
  return absl::OkStatus();
}

absl::Status Run(const std::string& dir) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  MESHSEG_ASSIGN_OR_RETURN(const PartFile small, WritePart(absl::GetFlag(FLAGS_small_part), 0.0, dir));
  MESHSEG_ASSIGN_OR_RETURN(
      const PartFile large,
      WritePart(absl::GetFlag(FLAGS_large_part), absl::GetFlag(FLAGS_large_voxel), dir));

  server::ServerOptions options;
  options.listen = "127.0.0.1:0";
  options.workers = cores;
  options.spool_dir = dir + "/spool";
  options.shutdown_grace = absl::Seconds(1);
  MESHSEG_ASSIGN_OR_RETURN(std::unique_ptr<server::Server> server,
                           server::Server::Start(std::move(options)));
  std::printf("server %s, %d workers\n", server->address().c_str(), cores);

  absl::Status status = SmallJobs(server->address(), small, absl::GetFlag(FLAGS_clients),
                                  absl::GetFlag(FLAGS_jobs));
  if (status.ok()) {
    status = LargeUpload(server->address(), large, absl::GetFlag(FLAGS_uploads),
                         absl::GetFlag(FLAGS_large_e2e));
  }
  server->Shutdown();
  return status;
}

}  // namespace
}  // namespace meshseg

int main(int argc, char** argv) {
  absl::ParseCommandLine(argc, argv);
  if (absl::GetFlag(FLAGS_clients) < 1 || absl::GetFlag(FLAGS_jobs) < 1 ||
      absl::GetFlag(FLAGS_uploads) < 1) {
    std::fprintf(stderr, "--clients, --jobs and --uploads must be at least 1\n");
    return 2;
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    absl::StrCat("meshseg_service_bench_", getpid());
  std::filesystem::create_directories(dir);
  const absl::Status status = meshseg::Run(dir.string());
  std::filesystem::remove_all(dir);
  if (!status.ok()) {
    std::fprintf(stderr, "service_throughput_bench: %s\n", status.ToString().c_str());
    return 1;
  }
  return 0;
}
