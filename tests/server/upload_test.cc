// Upload over loopback: every supported format round-trips and gives the
// offline JSON byte for byte; bad uploads get a clear status or a FAILED
// job, leave no spool file, and do not disturb the server.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/proto/sha256.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::SplitBox;
using testing_server::Eventually;
using testing_server::FreshDir;
using testing_server::TestServer;

absl::StatusOr<std::string> OfflineJson(const std::string& path) {
  absl::StatusOr<PipelineResult> r = RunPipeline(path);
  if (!r.ok()) return r.status();
  return ResultJson(ToProto(*r));
}

// Sends `header` then `chunks` on one Upload call and returns its status.
grpc::Status RawUpload(MeshsegClient& client, const v1::UploadHeader& header,
                       const std::vector<std::string>& chunks, v1::UploadResponse* response) {
  grpc::ClientContext context;
  auto writer = client.stub().Upload(&context, response);
  v1::UploadRequest request;
  *request.mutable_header() = header;
  writer->Write(request);
  for (const std::string& chunk : chunks) {
    request.set_chunk(chunk);
    if (!writer->Write(request)) break;
  }
  writer->WritesDone();
  return writer->Finish();
}

v1::UploadHeader Header(const std::string& name, const std::string& data) {
  v1::UploadHeader h;
  h.set_file_name(name);
  h.set_total_size(static_cast<int64_t>(data.size()));
  return h;
}

struct Format {
  std::string file;
  std::function<void(const testing_files::TestMesh&, const std::string&)> write;
};

TEST(Upload, EveryMeshFormatGivesTheOfflineJsonByteForByte) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  const testing_files::TestMesh box = SplitBox(3, {2.0, 1.0, 0.5});
  const std::vector<Format> formats = {
      {"box_ascii.stl", testing_files::WriteStlAscii},
      {"box_binary.stl", testing_files::WriteStlBinary},
      {"box.obj", testing_files::WriteObj},
      {"box.off", testing_files::WriteOff},
      {"box_ascii.ply", testing_files::WritePlyAscii},
      {"box_binary.ply", testing_files::WritePlyBinary},
      {"box_binary_big_endian.ply", testing_files::WritePlyBinaryBigEndian},
  };
  std::map<std::string, std::string> json;
  for (const Format& f : formats) {
    const std::string path = dir + "/" + f.file;
    f.write(box, path);
    const absl::StatusOr<std::string> offline = OfflineJson(path);
    ASSERT_TRUE(offline.ok()) << f.file << ": " << offline.status();
    const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(path);
    ASSERT_TRUE(remote.ok()) << f.file << ": " << remote.status();
    EXPECT_EQ(remote->face_labels_size(), static_cast<int>(box.f.size())) << f.file;
    EXPECT_EQ(*ResultJson(*remote), *offline) << f.file;
    json[f.file] = *offline;
  }
  // Both hold the same doubles: the big-endian bytes were decoded right.
  EXPECT_EQ(json["box_binary_big_endian.ply"], json["box_ascii.ply"]);
}

// Returns the vertices and faces of `mesh` in its own order.
testing_files::TestMesh ToTestMesh(const TriMesh& mesh) {
  testing_files::TestMesh m;
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    m.v.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> t{};
    int c = 0;
    for (const auto vh : mesh.fv_range(fh)) t[c++] = vh.idx();
    m.f.push_back(t);
  }
  return m;
}

// A CT-like part with planes, cylinders and tori (plate_boss, coarse voxels):
// the same bytes from server and offline in several formats, and the result
// really has many regions of several surface types.
TEST(Upload, GeneratedMultiRegionPartGivesTheOfflineJsonByteForByte) {
  constexpr int kMinRegions = 6;  // 11 at h = 1 (12 primitives; the edge round is too thin)
  const absl::StatusOr<GeneratedPart> part = GeneratePart("plate_boss", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  const testing_files::TestMesh mesh = ToTestMesh(part->mesh.tri);
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  ASSERT_TRUE(WriteMesh(part->mesh.tri, dir + "/plate_boss.ply").ok());  // little-endian
  testing_files::WritePlyBinaryBigEndian(mesh, dir + "/plate_boss_big_endian.ply");
  testing_files::WriteStlBinary(mesh, dir + "/plate_boss.stl");
  testing_files::WriteObj(mesh, dir + "/plate_boss.obj");
  std::map<std::string, std::string> json;
  for (const std::string file :
       {"plate_boss.ply", "plate_boss_big_endian.ply", "plate_boss.stl", "plate_boss.obj"}) {
    const std::string path = dir + "/" + file;
    const absl::StatusOr<std::string> offline = OfflineJson(path);
    ASSERT_TRUE(offline.ok()) << file << ": " << offline.status();
    const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(path);
    ASSERT_TRUE(remote.ok()) << file << ": " << remote.status();
    EXPECT_EQ(*ResultJson(*remote), *offline) << file;
    json[file] = *offline;

    ASSERT_EQ(remote->face_labels_size(), static_cast<int>(mesh.f.size())) << file;
    EXPECT_GE(remote->regions_size(), kMinRegions) << file;
    std::set<v1::SurfaceType> types;
    for (const v1::Region& r : remote->regions()) types.insert(r.type());
    EXPECT_TRUE(types.contains(v1::SURFACE_TYPE_PLANE)) << file;
    EXPECT_TRUE(types.contains(v1::SURFACE_TYPE_CYLINDER)) << file;
    EXPECT_TRUE(types.contains(v1::SURFACE_TYPE_TORUS)) << file;
    std::set<int> used;
    for (int label : remote->face_labels()) used.insert(label);
    EXPECT_GE(used.size(), static_cast<std::size_t>(kMinRegions)) << file << ": labels in use";
  }
  EXPECT_EQ(json["plate_boss_big_endian.ply"], json["plate_boss.ply"]) << "the same doubles";
}

// Point clouds go through reconstruction on both paths; the result (and the
// label per input point) must be the same bytes.
TEST(Upload, EveryPointCloudFormatGivesTheOfflineJsonByteForByte) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  const testing_files::TestMesh box = SplitBox(16, {2.0, 1.5, 1.0});  // 1538 points
  const std::vector<Format> formats = {
      {"box.xyz", testing_files::WriteXyz},
      {"box_normals.xyz", testing_files::WriteXyzNormals},
      {"box.pwn", testing_files::WritePwn},
      {"box_points_ascii.ply", testing_files::WritePlyPointsAscii},
      {"box_points_binary.ply", testing_files::WritePlyPointsBinary},
  };
  for (const Format& f : formats) {
    const std::string path = dir + "/" + f.file;
    f.write(box, path);
    const absl::StatusOr<std::string> offline = OfflineJson(path);
    ASSERT_TRUE(offline.ok()) << f.file << ": " << offline.status();
    const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(path);
    ASSERT_TRUE(remote.ok()) << f.file << ": " << remote.status();
    EXPECT_GT(remote->face_labels_size(), 0) << f.file;
    EXPECT_EQ(*ResultJson(*remote), *offline) << f.file;
  }
  EXPECT_TRUE(Eventually([&] { return server.SpoolFiles() == static_cast<int64_t>(formats.size()); })) << "one result per job";
}

TEST(Upload, SmallChunksAndAFormatHintWork) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.mesh";  // extension says nothing
  testing_files::WriteOff(SplitBox(2, {1, 1, 1}), path);
  const absl::StatusOr<v1::SegmentationResult> r =
      client.Segment(path, {.format_hint = "off", .chunk_bytes = 100});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(r->mesh().face_count(), 48);
}

TEST(Upload, BadUploadsGetAClearStatusAndLeaveNoSpoolFile) {
  testing_server::Gate gate;
  TestServer server({.workers = 1, .max_upload_bytes = 4096, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  // A good job is running (held by the gate) while the bad uploads arrive.
  const std::string good = FreshDir("files") + "/good.off";
  testing_files::WriteOff(SplitBox(2, {1, 1, 1}), good);
  const absl::StatusOr<v1::UploadResponse> running = client.Upload(good);
  ASSERT_TRUE(running.ok()) << running.status();
  ASSERT_TRUE(Eventually([&] { return gate.entered == 1; }));

  const std::string data(1000, ' ');
  v1::UploadResponse response;

  v1::UploadHeader truncated = Header("part.stl", data);
  truncated.set_total_size(2000);
  grpc::Status s = RawUpload(client, truncated, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(s.error_message(), HasSubstr("truncated"));
  EXPECT_THAT(s.error_message(), HasSubstr("part.stl"));

  v1::UploadHeader longer = Header("part.stl", data);
  longer.set_total_size(10);
  s = RawUpload(client, longer, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);

  v1::UploadHeader oversized = Header("big.stl", data);
  oversized.set_total_size(5000);
  s = RawUpload(client, oversized, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_THAT(s.error_message(), HasSubstr("4096"));

  v1::UploadHeader checksum = Header("part.stl", data);
  checksum.set_sha256(std::string(64, '0'));
  s = RawUpload(client, checksum, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(s.error_message(), HasSubstr("sha256 mismatch"));

  v1::UploadHeader unknown = Header("notes.txt", "just text\n");
  s = RawUpload(client, unknown, {"just text\n"}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);

  v1::UploadHeader hint = Header("part.stl", data);
  hint.set_format_hint("step");
  s = RawUpload(client, hint, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(s.error_message(), HasSubstr("step"));

  v1::UploadHeader options = Header("part.stl", data);
  options.mutable_options()->set_angle_tolerance_deg(-3);
  s = RawUpload(client, options, {data}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);

  {  // chunks without a header
    grpc::ClientContext context;
    auto writer = client.stub().Upload(&context, &response);
    v1::UploadRequest chunk;
    chunk.set_chunk(data);
    writer->Write(chunk);
    writer->WritesDone();
    s = writer->Finish();
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_THAT(s.error_message(), HasSubstr("header"));
  }
  EXPECT_EQ(server.SpoolFiles(), 1) << "only the running job's upload";
  const absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  ASSERT_EQ(jobs->size(), 1u) << "no job may be created by a bad upload";
  EXPECT_EQ(jobs->front().job_id(), running->job_id());
  EXPECT_EQ(testing_server::HealthStatus(server.address()), 1) << "still SERVING";

  gate.open.Notify();
  const absl::StatusOr<v1::Job> done = client.Watch(running->job_id());
  ASSERT_TRUE(done.ok()) << done.status();
  EXPECT_EQ(done->state(), v1::JOB_STATE_SUCCEEDED) << "the running job is unaffected";
  EXPECT_EQ(done->face_count(), 48);
  EXPECT_TRUE(Eventually([&] { return server.SpoolFiles() == 1; })) << "only its result";
}

TEST(Upload, ClientDisconnectMidStreamLeavesNoSpoolFile) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string chunk(64 * 1024, 'x');
  v1::UploadHeader header;
  header.set_file_name("part.stl");
  header.set_total_size(int64_t{100} << 20);
  grpc::ClientContext context;
  v1::UploadResponse response;
  auto writer = client.stub().Upload(&context, &response);
  v1::UploadRequest request;
  *request.mutable_header() = header;
  ASSERT_TRUE(writer->Write(request));
  request.set_chunk(chunk);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(writer->Write(request));
  ASSERT_TRUE(Eventually([&] { return server.SpoolFiles() == 1; }));  // receiving
  context.TryCancel();
  EXPECT_EQ(writer->Finish().error_code(), grpc::StatusCode::CANCELLED);
  EXPECT_TRUE(Eventually([&] { return server.SpoolFiles() == 0; }));
  EXPECT_TRUE(client.ListJobs()->empty());
  EXPECT_EQ(testing_server::HealthStatus(server.address()), 1);
}

TEST(Upload, UnreadableContentFailsTheJobWithAMessageAndOthersStillRun) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  const std::string nan = dir + "/nan_vertex.obj";
  testing_files::WriteText(nan, "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  const std::string truncated = dir + "/truncated_binary.stl";
  testing_files::WriteStlBinary(SplitBox(2, {1, 1, 1}), truncated);
  std::filesystem::resize_file(truncated, 84 + 50 * 10 + 7);
  const std::string good = dir + "/good.obj";
  testing_files::WriteObj(SplitBox(2, {1, 1, 1}), good);

  const std::string nan_points = dir + "/nan_point.xyz";
  testing_files::WriteText(nan_points, "0 0 0\n1 0 0\nnan 1 0\n");
  const std::string malformed = dir + "/bad_count.off";
  testing_files::WriteText(malformed, "OFF\n3 1 0\n0 0 0\n1 0 0\n");

  for (const std::string& bad : {nan, truncated, nan_points, malformed}) {
    const std::string name = std::filesystem::path(bad).filename().string();
    const absl::StatusOr<v1::UploadResponse> up = client.Upload(bad);
    ASSERT_TRUE(up.ok()) << name << ": the upload itself is fine: " << up.status();
    const absl::StatusOr<v1::Job> job = client.Watch(up->job_id());
    ASSERT_TRUE(job.ok()) << job.status();
    EXPECT_EQ(job->state(), v1::JOB_STATE_FAILED) << name;
    EXPECT_EQ(job->error_code(), static_cast<int>(absl::StatusCode::kInvalidArgument)) << name;
    EXPECT_THAT(job->error_message(), HasSubstr(name));
    const absl::StatusOr<v1::SegmentationResult> r = client.Segment(bad);  // the same via Segment
    EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument) << r.status();
    EXPECT_THAT(r.status().message(), HasSubstr(name));
    EXPECT_EQ(client.Result(up->job_id()).status().code(), absl::StatusCode::kFailedPrecondition)
        << "a FAILED job has no result";
  }
  const absl::StatusOr<v1::SegmentationResult> ok = client.Segment(good);
  ASSERT_TRUE(ok.ok()) << ok.status();
  // The worker removes the upload once the outcome is recorded (crash-safe
  // order), so a moment after the client saw it.
  EXPECT_TRUE(Eventually([&] { return server.SpoolFiles() == 1; }))
      << "only the good job's result stays";
  EXPECT_EQ(testing_server::HealthStatus(server.address()), 1);
}

}  // namespace
}  // namespace meshseg
