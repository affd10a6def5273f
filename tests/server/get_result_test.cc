#include <gtest/gtest.h>

#include "meshseg/proto/sha256.h"
#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

// Returns the bytes GetResult streams from `offset` in chunks of at most
// `chunk_size` (each chunk's offset and total checked), or the call's
// status; counts the chunks in `chunks`.
absl::StatusOr<std::string> Download(MeshsegClient& client, const v1::Job& job, int64_t offset,
                                     int chunk_size, int* chunks = nullptr) {
  grpc::ClientContext context;
  v1::GetResultRequest request;
  request.set_job_id(job.job_id());
  request.set_chunk_size(chunk_size);
  request.set_offset(offset);
  auto reader = client.stub().GetResult(&context, request);
  std::string bytes;
  v1::ResultChunk chunk;
  while (reader->Read(&chunk)) {
    EXPECT_EQ(chunk.offset(), offset + static_cast<int64_t>(bytes.size()));
    EXPECT_LE(chunk.data().size(), static_cast<std::size_t>(chunk_size));
    EXPECT_EQ(chunk.total_size(), job.result_size());
    bytes += chunk.data();
    if (chunks != nullptr) ++*chunks;
  }
  const grpc::Status status = reader->Finish();
  if (!status.ok()) {
    return absl::Status(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
  }
  return bytes;
}

TEST(GetResult, StreamsTheResultInChunksWithOffsets) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(6, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::Job> job = client.Watch(id);
  ASSERT_TRUE(job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) << job.status();

  int chunks = 0;
  const absl::StatusOr<std::string> downloaded = Download(client, *job, 0, 256, &chunks);
  ASSERT_TRUE(downloaded.ok()) << downloaded.status();
  const std::string& bytes = *downloaded;
  EXPECT_EQ(static_cast<int64_t>(bytes.size()), job->result_size());
  EXPECT_GT(chunks, 1);
  v1::SegmentationResult result;
  ASSERT_TRUE(result.ParseFromString(bytes));
  EXPECT_EQ(result.face_labels_size(), 6 * 6 * 12);
}

// The job names the result's size and SHA-256; a download cut off resumes
// from any offset and the pieces hash to that digest.
TEST(GetResult, ResumesFromAnOffsetAndMatchesTheJobsSha256) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(6, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::Job> job = client.Watch(id);
  ASSERT_TRUE(job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) << job.status();
  ASSERT_TRUE(IsSha256Hex(job->result_sha256())) << job->result_sha256();

  const absl::StatusOr<std::string> whole = Download(client, *job, 0, 100);
  ASSERT_TRUE(whole.ok()) << whole.status();
  ASSERT_EQ(static_cast<int64_t>(whole->size()), job->result_size());
  const int64_t cut = job->result_size() / 3;
  const absl::StatusOr<std::string> rest = Download(client, *job, cut, 100);
  ASSERT_TRUE(rest.ok()) << rest.status();
  EXPECT_EQ(*rest, whole->substr(cut));
  Sha256 digest;
  digest.Update(std::string_view(*whole).substr(0, cut));
  digest.Update(*rest);
  EXPECT_EQ(digest.HexDigest(), job->result_sha256());

  EXPECT_EQ(Download(client, *job, job->result_size(), 100)->size(), 0u);  // nothing left
  for (const int64_t bad : {int64_t{-1}, job->result_size() + 1}) {
    const absl::StatusOr<std::string> r = Download(client, *job, bad, 100);
    EXPECT_EQ(r.status().code(), absl::StatusCode::kOutOfRange) << bad;
  }
}

TEST(GetResult, UnfinishedJobIsFailedPrecondition) {
  Gate gate;
  TestServer server({.workers = 1, .runner = gate.Runner()});
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(1, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::SegmentationResult> r = client.Result(id);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kFailedPrecondition) << r.status();
  gate.open.Notify();
}

TEST(GetResult, StepFormatStreamsTheStepFileOfAJobThatAskedForIt) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  const std::string path = dir + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(6, {2, 1, 0.5}), path);
  const std::string id = client.Upload(path, {.step = true, .step_unit = "cm"})->job_id();
  const absl::StatusOr<v1::Job> job = client.Watch(id);
  ASSERT_TRUE(job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) << job.status();
  const absl::StatusOr<v1::SegmentationResult> result = client.Result(id);
  ASSERT_TRUE(result.ok()) << result.status();
  // What the brep stage wrote (the offline pipeline's geometry is tested in
  // tests/core/brep; here: the server keeps and streams that file).
  const v1::BrepReport& brep = result->brep();
  EXPECT_EQ(brep.error(), "");
  EXPECT_GE(brep.face_count(), 1);
  EXPECT_EQ(brep.length_unit(), "cm");
  ASSERT_GT(job->step_size(), 0);
  EXPECT_EQ(job->step_size(), brep.step_size());

  const std::string step_path = dir + "/box.step";
  ASSERT_TRUE(client.SaveStep(id, step_path).ok());
  const std::string step = testing_files::ReadText(step_path);
  EXPECT_EQ(static_cast<int64_t>(step.size()), job->step_size());
  EXPECT_NE(step.find("ISO-10303-21;"), std::string::npos);
  EXPECT_NE(step.find("SI_UNIT(.CENTI.,.METRE.)"), std::string::npos);
  EXPECT_NE(step.find("ADVANCED_FACE"), std::string::npos);
}

TEST(GetResult, StepFormatOfAJobWithoutStepIsNotFoundSayingHowToAsk) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(2, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::Job> job = client.Watch(id);
  ASSERT_TRUE(job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) << job.status();
  EXPECT_EQ(job->step_size(), 0);
  const absl::Status s = client.SaveStep(id, FreshDir("files") + "/never.step");
  EXPECT_EQ(s.code(), absl::StatusCode::kNotFound) << s;
  EXPECT_NE(s.message().find("step = true"), std::string::npos) << s;
}

}  // namespace
}  // namespace meshseg
