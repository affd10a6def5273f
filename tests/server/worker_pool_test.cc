// The worker pool under load: 8 clients x 3 jobs at once, each job a mesh
// of its own size, so a lost or mixed-up job shows as a wrong face count.
#include <thread>

#include <gtest/gtest.h>

#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::FreshDir;
using testing_server::TestServer;

TEST(WorkerPool, EightClientsThreeJobsEachAllCompleteUnmixed) {
  constexpr int kClients = 8;
  constexpr int kJobsPerClient = 3;
  TestServer server({.workers = 2, .queue_capacity = kClients * kJobsPerClient});
  const std::string dir = FreshDir("files");
  std::vector<std::string> paths;
  std::vector<int> faces;
  for (int k = 0; k < kClients * kJobsPerClient; ++k) {
    const int n = 1 + k % 6;
    paths.push_back(dir + "/part" + std::to_string(k) + ".off");
    const testing_files::TestMesh box = testing_files::SplitBox(n, {1.0 + k, 1, 1});
    testing_files::WriteOff(box, paths.back());
    faces.push_back(static_cast<int>(box.f.size()));
  }
  std::vector<std::string> errors(kClients);
  std::vector<std::vector<std::string>> job_ids(kClients);
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      MeshsegClient client = server.Client();
      for (int j = 0; j < kJobsPerClient; ++j) {
        const int k = c * kJobsPerClient + j;
        absl::StatusOr<v1::UploadResponse> up = client.Upload(paths[k]);
        if (!up.ok()) { errors[c] += up.status().ToString() + "; "; continue; }
        job_ids[c].push_back(up->job_id());
        absl::StatusOr<v1::Job> done = client.Watch(up->job_id());
        absl::StatusOr<v1::SegmentationResult> r = client.Result(up->job_id());
        if (!done.ok() || !r.ok()) { errors[c] += "job " + up->job_id() + " failed; "; continue; }
        if (done->file_name() != "part" + std::to_string(k) + ".off" ||
            r->face_labels_size() != faces[k] || done->face_count() != faces[k]) {
          errors[c] += "job " + up->job_id() + " mixed up; ";
        }
      }
    });
  }
  for (std::thread& t : clients) t.join();
  for (int c = 0; c < kClients; ++c) EXPECT_EQ(errors[c], "") << "client " << c;
  const absl::StatusOr<std::vector<v1::Job>> jobs = server.Client().ListJobs();
  ASSERT_TRUE(jobs.ok());
  ASSERT_EQ(jobs->size(), static_cast<std::size_t>(kClients * kJobsPerClient));
  for (const v1::Job& job : *jobs) EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED) << job.job_id();
}

TEST(WorkerPool, QueueFullGivesResourceExhausted) {
  testing_server::Gate gate;
  TestServer server({.workers = 1, .queue_capacity = 2, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  ASSERT_TRUE(client.Upload(path).ok());  // running (held by the gate)
  ASSERT_TRUE(testing_server::Eventually([&] { return gate.entered == 1; }));
  ASSERT_TRUE(client.Upload(path).ok());  // queued 1
  ASSERT_TRUE(client.Upload(path).ok());  // queued 2
  const absl::StatusOr<v1::UploadResponse> full = client.Upload(path);
  EXPECT_EQ(full.status().code(), absl::StatusCode::kResourceExhausted) << full.status();
  EXPECT_NE(full.status().message().find("full"), absl::string_view::npos);
  gate.open.Notify();
  ASSERT_TRUE(testing_server::Eventually([&] {
    auto jobs = client.ListJobs();
    int done = 0;
    for (const v1::Job& j : *jobs) done += j.state() == v1::JOB_STATE_SUCCEEDED;
    return done == 3;
  }));
  EXPECT_TRUE(client.Upload(path).ok()) << "room again once the queue drains";
}

}  // namespace
}  // namespace meshseg
