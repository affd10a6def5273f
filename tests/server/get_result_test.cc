#include <gtest/gtest.h>

#include "tests/server/test_files.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using testing_server::FreshDir;
using testing_server::Gate;
using testing_server::TestServer;

TEST(GetResult, StreamsTheResultInChunksWithOffsets) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string path = FreshDir("files") + "/box.off";
  testing_files::WriteOff(testing_files::SplitBox(6, {1, 1, 1}), path);
  const std::string id = client.Upload(path)->job_id();
  const absl::StatusOr<v1::Job> job = client.Watch(id);
  ASSERT_TRUE(job.ok() && job->state() == v1::JOB_STATE_SUCCEEDED) << job.status();

  grpc::ClientContext context;
  v1::GetResultRequest request;
  request.set_job_id(id);
  request.set_chunk_size(256);
  auto reader = client.stub().GetResult(&context, request);
  std::string bytes;
  int chunks = 0;
  v1::ResultChunk chunk;
  while (reader->Read(&chunk)) {
    EXPECT_EQ(chunk.offset(), static_cast<int64_t>(bytes.size()));
    EXPECT_LE(chunk.data().size(), 256u);
    EXPECT_EQ(chunk.total_size(), job->result_size());
    bytes += chunk.data();
    ++chunks;
  }
  ASSERT_TRUE(reader->Finish().ok());
  EXPECT_EQ(static_cast<int64_t>(bytes.size()), job->result_size());
  EXPECT_GT(chunks, 1);
  v1::SegmentationResult result;
  ASSERT_TRUE(result.ParseFromString(bytes));
  EXPECT_EQ(result.face_labels_size(), 6 * 6 * 12);
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
