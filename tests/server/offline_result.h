// Small generated parts for the process tests and what an offline
// `meshseg segment` (the CLI binary, MESHSEG_BIN_DIR) writes for them, so a
// job's result fetched from any server can be compared byte for byte.
#ifndef MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_
#define MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
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

// The result JSON of a finished job as the CLI writes it (`meshseg result`).
inline absl::StatusOr<std::string> ServerJson(MeshsegClient& client, const std::string& job_id) {
  absl::StatusOr<v1::SegmentationResult> result = client.Result(job_id);
  if (!result.ok()) return result.status();
  return ResultJson(*result);
}

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_OFFLINE_RESULT_H_
