// Small generated parts for the process tests and what an offline
// `meshseg segment` (the CLI binary, MESHSEG_BIN_DIR) writes for them, so a
// job's result fetched from any server can be compared byte for byte.
#ifndef MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_
#define MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/time/time.h"
#include "client/meshseg_client.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/result_json.h"

namespace meshseg::testing_server {

struct TestPart {
  std::string path;
  std::string offline_json;  // `meshseg segment PATH -o X.json`, X.json's bytes
};

inline std::string ReadWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes generated part `name` at voxel size `h` to DIR/FILE and segments it
// offline with the CLI. offline_json is empty if either step failed.
inline TestPart MakePart(const std::string& dir, const std::string& file, const std::string& name,
                         double h) {
  TestPart part{.path = dir + "/" + file, .offline_json = {}};
  const absl::StatusOr<GeneratedPart> generated = GeneratePart(name, {.voxel_size = h});
  if (!generated.ok() || !WriteMesh(generated->mesh.tri, part.path).ok()) return part;
  const std::string json = part.path + ".offline.json";
  const std::string cmd = absl::StrCat(MESHSEG_BIN_DIR, "/meshseg segment ", part.path, " -o ",
                                       json, " >/dev/null 2>&1");
  if (std::system(cmd.c_str()) == 0) part.offline_json = ReadWhole(json);
  return part;
}

// The parts of the process tests, written to `dir`: three small ones of
// different shapes (a mixed-up result shows; coarse voxels keep each job a
// fraction of a second) and, last, one whose job runs a second or more (to
// be caught running).
inline std::vector<TestPart> MakeTestParts(const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::vector<TestPart> parts;
  const std::vector<std::string> names = PartNames();
  for (int i = 0; i < 3; ++i) {
    parts.push_back(MakePart(dir, "small" + std::to_string(i) + ".ply", names[i], 1.2));
  }
  parts.push_back(MakePart(dir, "long.ply", "test_piece", 0.8));
  return parts;
}

// The result JSON of a finished job as the CLI writes it (`meshseg result`).
inline absl::StatusOr<std::string> ServerJson(MeshsegClient& client, const std::string& job_id) {
  absl::StatusOr<v1::SegmentationResult> result = client.Result(job_id);
  if (!result.ok()) return result.status();
  return ResultJson(*result);
}

// Watches `id` to its end and checks it SUCCEEDED with `part`'s offline
// result, byte for byte; returns the job.
inline v1::Job ExpectOfflineResult(MeshsegClient& client, const std::string& id,
                                   const TestPart& part, absl::Duration timeout) {
  const absl::StatusOr<v1::Job> job = client.Watch(id, {}, timeout);
  EXPECT_TRUE(job.ok()) << id << ": " << job.status();
  if (!job.ok()) return {};
  EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED) << id << ": " << job->error_message();
  const absl::StatusOr<std::string> json = ServerJson(client, id);
  EXPECT_TRUE(json.ok()) << json.status();
  EXPECT_TRUE(json.ok() && *json == part.offline_json)
      << id << " differs from offline " << part.path;
  return *job;
}

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_
