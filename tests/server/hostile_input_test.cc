// The hostile-input matrix: at least 40 malformed, lying, extreme or
// abusive uploads and calls over loopback gRPC, table-driven. Each gets its
// documented status (the call fails with a code and a message naming the
// problem) or a FAILED job whose message names it; meanwhile a good job
// finishes with the offline result, health stays SERVING, every Job stays
// readable by ListJobs (valid UTF-8), the test process's peak RSS stays
// bounded, and nothing is written outside the spool.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/proto/sha256.h"
#include "meshseg/proto/utf8.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::SplitBox;
using testing_server::FreshDir;
using testing_server::HealthStatus;
using testing_server::TestServer;

// How the bytes are sent.
enum class Send {
  kNormal,       // header, then the bytes in 64 KiB chunks
  kNoHeader,     // the bytes only
  kNothing,      // close the stream at once
  kHeaderTwice,  // header, bytes, header again
  kExtraBytes,   // 10 bytes more than total_size
  kShortBytes,   // 10 bytes fewer than total_size
};

// What must happen.
enum class Outcome { kCallFails, kJobFails, kJobSucceeds };

struct HostileUpload {
  std::string label;
  std::string file_name;
  std::string bytes;
  Outcome outcome;
  absl::StatusCode code;  // of the call, or the job's error_code
  std::string message;    // a substring of the call's or job's message
  Send send = Send::kNormal;
  std::function<void(v1::UploadHeader&)> tweak = {};
};

std::string Le32(uint32_t v) {
  std::string s(4, '\0');
  std::memcpy(s.data(), &v, 4);
  return s;
}

std::string BinaryStl(uint32_t declared, int written) {
  std::string s(80, 'b');
  s += Le32(declared);
  for (int t = 0; t < written; ++t) {
    float f[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    f[3 + 3 * (t % 3)] = static_cast<float>(t);  // distinct triangles
    s.append(reinterpret_cast<const char*>(f), sizeof f);
    s.append(2, '\0');
  }
  return s;
}

std::string PlyHeader(const std::string& format, int64_t vertices, int64_t faces) {
  return absl::StrCat("ply\nformat ", format, " 1.0\nelement vertex ", vertices,
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face ",
                      faces, "\nproperty list uchar int vertex_indices\nend_header\n");
}

// A tetrahedron as OFF text with its coordinates scaled by `s`.
std::string Tetrahedron(double s) {
  return absl::StrCat("OFF\n4 4 0\n0 0 0\n", s, " 0 0\n0 ", s, " 0\n0 0 ", s,
                      "\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
}

// A flat 100-gon (a disc) as OFF.
std::string HundredGon() {
  std::string s = "OFF\n100 1 0\n";
  for (int i = 0; i < 100; ++i) {
    const double a = 2 * M_PI * i / 100;
    absl::StrAppend(&s, std::cos(a), " ", std::sin(a), " 0\n");
  }
  s += "100";
  for (int i = 0; i < 100; ++i) absl::StrAppend(&s, " ", i);
  return s + "\n";
}

std::vector<HostileUpload> Cases(const std::string& box_obj) {
  using C = absl::StatusCode;
  const Outcome call = Outcome::kCallFails, job = Outcome::kJobFails;
  return {
      // The stream itself.
      {"no header", "a.obj", box_obj, call, C::kInvalidArgument, "first message must be the header",
       Send::kNoHeader},
      {"empty stream", "a.obj", "", call, C::kInvalidArgument, "empty stream", Send::kNothing},
      {"header twice", "a.obj", box_obj, call, C::kInvalidArgument, "header sent again",
       Send::kHeaderTwice},
      {"more bytes than declared", "a.obj", box_obj, call, C::kInvalidArgument, "header declared",
       Send::kExtraBytes},
      {"fewer bytes than declared", "a.obj", box_obj, call, C::kInvalidArgument, "truncated",
       Send::kShortBytes},
      {"no file name", "", box_obj, call, C::kInvalidArgument, "no file_name"},
      {"zero total_size", "a.obj", box_obj, call, C::kInvalidArgument,
       "total_size must be positive", Send::kNormal,
       [](v1::UploadHeader& h) { h.set_total_size(0); }},
      {"negative total_size", "a.obj", box_obj, call, C::kInvalidArgument,
       "total_size must be positive", Send::kNormal,
       [](v1::UploadHeader& h) { h.set_total_size(-5); }},
      {"total_size over the limit", "a.obj", box_obj, call, C::kResourceExhausted,
       "exceed the limit", Send::kNormal,
       [](v1::UploadHeader& h) { h.set_total_size(int64_t{1} << 40); }},
      {"checksum not hex", "a.obj", box_obj, call, C::kInvalidArgument, "64 hex digits",
       Send::kNormal, [](v1::UploadHeader& h) { h.set_sha256("xyz"); }},
      {"wrong checksum", "a.obj", box_obj, call, C::kInvalidArgument, "sha256 mismatch",
       Send::kNormal, [](v1::UploadHeader& h) { h.set_sha256(std::string(64, 'a')); }},
      {"unknown format hint", "a.obj", box_obj, call, C::kInvalidArgument, "not one of stl",
       Send::kNormal, [](v1::UploadHeader& h) { h.set_format_hint("step"); }},
      {"angle tolerance 90", "a.obj", box_obj, call, C::kInvalidArgument,
       "angle_tolerance_deg must be in (0, 90), got 90", Send::kNormal,
       [](v1::UploadHeader& h) { h.mutable_options()->set_angle_tolerance_deg(90); }},
      {"distance tolerance NaN", "a.obj", box_obj, call, C::kInvalidArgument,
       "distance_tolerance must be in (0, 100]", Send::kNormal,
       [](v1::UploadHeader& h) { h.mutable_options()->set_distance_tolerance(std::nan("")); }},
      {"distance tolerance negative", "a.obj", box_obj, call, C::kInvalidArgument,
       "distance_tolerance must be in (0, 100], got -1", Send::kNormal,
       [](v1::UploadHeader& h) { h.mutable_options()->set_distance_tolerance(-1); }},
      {"unknown step unit", "a.obj", box_obj, call, C::kInvalidArgument,
       "step_unit \"furlong\" is not one of mm, cm", Send::kNormal,
       [](v1::UploadHeader& h) {
         h.set_step(true);
         h.set_step_unit("furlong");
       }},
      {"unknown length unit", "a.obj", box_obj, call, C::kInvalidArgument,
       "length_unit \"yard\" is not one of mm, cm", Send::kNormal,
       [](v1::UploadHeader& h) { h.set_length_unit("yard"); }},
      {"unknown content", "blob.bin", std::string("\x01\x02\x03garbage\x7f", 11), call,
       C::kInvalidArgument, "unknown format"},
      // Lying or truncated headers, every format.
      {"non-UTF-8 OFF counts", "a.off", std::string("OFF\n\xff\xfe 3 0\n", 11), job,
       C::kInvalidArgument, "got \"\\xff\\xfe\""},
      {"binary STL truncated", "a.stl", BinaryStl(100, 2), job, C::kInvalidArgument, "a.stl"},
      // Refused at upload by the memory estimate from the header.
      {"binary STL declares 4e9 triangles", "a.stl", BinaryStl(0xFFFFFFFFu, 2), call,
       C::kResourceExhausted, "4294967295 faces"},
      {"ASCII STL cut mid facet", "a.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0", job,
       C::kInvalidArgument, "a.stl"},
      {"OFF declares 1e9 vertices", "a.off", "OFF\n1000000000 1 0\n0 0 0\n", call,
       C::kResourceExhausted, "1000000000 vertices need an estimated"},
      {"OFF declares more faces than it holds", "a.off",
       "OFF\n3 5 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", job, C::kInvalidArgument, "a.off"},
      {"OFF negative index", "a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", job,
       C::kInvalidArgument, "vertex index -1 out of range"},
      {"OFF index out of range", "a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", job,
       C::kInvalidArgument, "vertex index 7 out of range"},
      {"OBJ index out of range", "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", job,
       C::kInvalidArgument, "a.obj"},
      {"OBJ negative index past the start", "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -8\n", job,
       C::kInvalidArgument, "a.obj"},
      {"OBJ NaN coordinate", "a.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n", job,
       C::kInvalidArgument, "non-finite"},
      {"OBJ Inf coordinate", "a.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n", job,
       C::kInvalidArgument, "non-finite"},
      {"OBJ comments only", "a.obj", "# nothing\n# here\n", job, C::kInvalidArgument, "a.obj"},
      {"coordinates 1e300", "big.off", Tetrahedron(1e300), job, C::kInvalidArgument,
       "beyond the +-1e+75"},
      {"PLY declares 1e9 faces", "a.ply",
       PlyHeader("ascii", 3, 1000000000) + "0 0 0\n1 0 0\n0 1 0\n", call,
       C::kResourceExhausted, "\"a.ply\": 1000000000 faces"},
      {"PLY ASCII header lies about vertices", "a.ply",
       PlyHeader("ascii", 9, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", job, C::kInvalidArgument,
       "a.ply"},
      {"PLY binary truncated", "a.ply",
       PlyHeader("binary_little_endian", 3, 1) + std::string(20, '\0'), job, C::kInvalidArgument,
       "a.ply"},
      {"PLY unknown type", "a.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n", call,
       C::kInvalidArgument, "unknown type"},
      {"PLY without end_header", "a.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", call,
       C::kInvalidArgument, "\"a.ply\": no \"end_header\""},
      {"all faces degenerate (collinear)", "a.off",
       "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n3 1 2 3\n", job, C::kInvalidArgument,
       "a.off"},
      {"1-point cloud", "a.xyz", "1 2 3\n", job, C::kInvalidArgument, "a.xyz"},
      {"NaN in a cloud", "a.xyz", "0 0 0\n1 0 0\nnan 1 0\n", job, C::kInvalidArgument,
       "non-finite"},
      {"PWN count lies", "a.pwn", "5\n0 0 0\n1 0 0\n", job, C::kInvalidArgument, "a.pwn"},
      // Valid but unusual input is segmented.
      {"100-gon face", "disc.off", HundredGon(), Outcome::kJobSucceeds, C::kOk, ""},
      {"path-like file name", "../../../escape/evil.obj", box_obj, Outcome::kJobSucceeds, C::kOk,
       ""},
      {"non-ASCII file name", "\xE9\x83\xA8\xE5\x93\x81.obj", box_obj, Outcome::kJobSucceeds,
       C::kOk, ""},
  };
}

// Sends `c` on one Upload call; returns its status and the job id.
grpc::Status Send(MeshsegClient& client, const HostileUpload& c, std::string* job_id) {
  v1::UploadHeader header;
  header.set_file_name(c.file_name);
  header.set_total_size(static_cast<int64_t>(c.bytes.size()));
  if (c.send == Send::kExtraBytes) header.set_total_size(header.total_size() - 10);
  if (c.send == Send::kShortBytes) header.set_total_size(header.total_size() + 10);
  if (c.tweak) c.tweak(header);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(30)));
  v1::UploadResponse response;
  auto writer = client.stub().Upload(&context, &response);
  v1::UploadRequest request;
  if (c.send != Send::kNoHeader && c.send != Send::kNothing) {
    *request.mutable_header() = header;
    writer->Write(request);
  }
  if (c.send != Send::kNothing) {
    for (std::size_t at = 0; at < c.bytes.size(); at += 64 << 10) {
      request.set_chunk(c.bytes.substr(at, 64 << 10));
      if (!writer->Write(request)) break;
    }
  }
  if (c.send == Send::kHeaderTwice) {
    *request.mutable_header() = header;
    writer->Write(request);
  }
  writer->WritesDone();
  const grpc::Status status = writer->Finish();
  *job_id = response.job_id();
  return status;
}

// Returns every path under `dir` except those under `skip`, sorted.
std::vector<std::string> FilesOutside(const std::filesystem::path& dir,
                                      const std::filesystem::path& skip) {
  std::vector<std::string> paths;
  for (auto it = std::filesystem::recursive_directory_iterator(dir);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->path() == skip) {
      it.disable_recursion_pending();
      continue;
    }
    paths.push_back(it->path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

long PeakRssKib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(HostileInput, EveryCaseGetsItsStatusAndTheServerStaysWhole) {
  const std::string files = FreshDir("files");
  const std::string box_path = files + "/box.obj";
  testing_files::WriteObj(SplitBox(3, {1, 2, 3}), box_path);
  const std::string box_obj = testing_files::ReadText(box_path);
  const std::string part_path = files + "/part.off";
  testing_files::WriteOff(SplitBox(6, {2, 1, 1}), part_path);
  const absl::StatusOr<PipelineResult> offline = RunPipeline(part_path);
  ASSERT_TRUE(offline.ok()) << offline.status();

  server::ServerOptions options;
  options.max_upload_bytes = 1 << 20;
  TestServer server(options);
  MeshsegClient client = server.Client();
  // TestServer's spool is FreshDir("spool"): a sibling of `files`.
  const std::filesystem::path scratch = std::filesystem::path(files).parent_path();
  const std::filesystem::path spool = files.substr(0, files.rfind("files")) + "spool";
  ASSERT_TRUE(std::filesystem::is_directory(spool)) << spool;
  const std::vector<std::string> outside_before = FilesOutside(scratch, spool);
  const long rss_before = PeakRssKib();

  // A good job in flight while the hostile ones arrive.
  const absl::StatusOr<v1::UploadResponse> good = client.Upload(part_path);
  ASSERT_TRUE(good.ok()) << good.status();

  const std::vector<HostileUpload> cases = Cases(box_obj);
  ASSERT_GE(cases.size(), 40u);
  std::vector<std::string> job_ids(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const HostileUpload& c = cases[i];
    const grpc::Status status = Send(client, c, &job_ids[i]);
    if (c.outcome == Outcome::kCallFails) {
      EXPECT_EQ(static_cast<int>(status.error_code()), static_cast<int>(c.code)) << c.label;
      EXPECT_THAT(status.error_message(), HasSubstr(c.message)) << c.label;
      EXPECT_TRUE(IsValidUtf8(status.error_message())) << c.label;
    } else {
      EXPECT_TRUE(status.ok()) << c.label << ": " << status.error_message();
    }
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const HostileUpload& c = cases[i];
    if (c.outcome == Outcome::kCallFails || job_ids[i].empty()) continue;
    const absl::StatusOr<v1::Job> job = client.Watch(job_ids[i], {}, absl::Seconds(60));
    ASSERT_TRUE(job.ok()) << c.label << ": " << job.status();
    if (c.outcome == Outcome::kJobSucceeds) {
      EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED) << c.label << ": " << job->error_message();
      EXPECT_THAT(job->file_name(), ::testing::MatchesRegex("[A-Za-z0-9._-]+")) << c.label;
      continue;
    }
    EXPECT_EQ(job->state(), v1::JOB_STATE_FAILED) << c.label;
    EXPECT_EQ(job->error_code(), static_cast<int>(c.code))
        << c.label << ": " << job->error_message();
    EXPECT_THAT(job->error_message(), HasSubstr(c.message)) << c.label;
  }

  // Calls on jobs that are not there or not in the right state.
  EXPECT_EQ(client.GetJob("job-0000000000000000").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.GetJob(std::string(5000, 'j')).status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Cancel("no-such-job").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Result("no-such-job").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client.Watch("no-such-job", {}, absl::Seconds(5)).status().code(),
            absl::StatusCode::kNotFound);
  const absl::StatusOr<v1::Job> done = client.Watch(good->job_id(), {}, absl::Seconds(120));
  ASSERT_TRUE(done.ok()) << done.status();
  EXPECT_EQ(client.Cancel(good->job_id()).status().code(), absl::StatusCode::kFailedPrecondition)
      << "cancel of a finished job";
  EXPECT_EQ(client.Cancel(good->job_id()).status().code(), absl::StatusCode::kFailedPrecondition)
      << "and again";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].outcome != Outcome::kJobFails || job_ids[i].empty()) continue;
    EXPECT_EQ(client.Result(job_ids[i]).status().code(), absl::StatusCode::kFailedPrecondition)
        << "a FAILED job has no result";
    break;
  }
  {
    grpc::ClientContext context;
    v1::GetResultRequest request;
    request.set_job_id(good->job_id());
    request.set_chunk_size(-1);
    auto reader = client.stub().GetResult(&context, request);
    v1::ResultChunk chunk;
    while (reader->Read(&chunk)) {
    }
    EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  }

  // The good job's result is the offline one.
  const absl::StatusOr<v1::SegmentationResult> result = client.Result(good->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(ResultJson(*result), ResultJson(ToProto(*offline)));

  // The server is whole: healthy, every job listable (the non-UTF-8 one
  // included), memory bounded, nothing outside the spool.
  EXPECT_EQ(HealthStatus(server.address()), 1);
  const absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  for (const v1::Job& job : *jobs) EXPECT_TRUE(IsValidUtf8(job.error_message())) << job.job_id();
  constexpr long kMaxGrowthKib = 512 << 10;
  EXPECT_LT(PeakRssKib() - rss_before, kMaxGrowthKib);
  EXPECT_EQ(FilesOutside(scratch, spool), outside_before) << "written outside the spool";
}

}  // namespace
}  // namespace meshseg
