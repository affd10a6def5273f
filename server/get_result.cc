#include <algorithm>
#include <fstream>
#include <vector>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/grpc_status.h"
#include "server/service.h"

namespace meshseg::server {
namespace {

constexpr int kDefaultChunkBytes = 1 << 20;
constexpr int kMaxChunkBytes = 4 << 20;  // gRPC's default message limit

// Returns OK if `job` has a result to fetch.
absl::Status CheckSucceeded(const v1::Job& job) {
  if (job.state() == v1::JOB_STATE_SUCCEEDED) return absl::OkStatus();
  return absl::FailedPreconditionError(absl::StrCat(
      "result: job \"", job.job_id(), "\" is ", v1::JobState_Name(job.state()),
      ", not JOB_STATE_SUCCEEDED",
      job.error_message().empty() ? "" : absl::StrCat(" (", job.error_message(), ")")));
}

}  // namespace

grpc::Status SegmentationService::GetResult(grpc::ServerContext* context,
                                            const v1::GetResultRequest* request,
                                            grpc::ServerWriter<v1::ResultChunk>* writer) {
  const absl::StatusOr<std::unique_ptr<StreamLimit::Slot>> slot = StreamSlot("result");
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  absl::StatusOr<v1::Job> job = OwnJob(*context, request->job_id());
  if (!job.ok()) return ToGrpcStatus(job.status());
  if (absl::Status s = CheckSucceeded(*job); !s.ok()) return ToGrpcStatus(s);
  if (request->chunk_size() < 0) {
    return ToGrpcStatus(absl::InvalidArgumentError(
        absl::StrCat("result: chunk_size must be >= 0, got ", request->chunk_size())));
  }

  const bool step = request->format() == v1::RESULT_FORMAT_STEP;
  if (!step && request->format() != v1::RESULT_FORMAT_UNSPECIFIED) {
    return ToGrpcStatus(absl::InvalidArgumentError(
        absl::StrCat("result: unknown format ", static_cast<int>(request->format()))));
  }
  if (step && job->step_size() == 0) {
    return ToGrpcStatus(absl::NotFoundError(absl::StrCat(
        "result: job \"", job->job_id(), "\" has no STEP file (upload with step = true; when it ",
        "was, the result's brep.error says why none was written)")));
  }
  const int64_t total_size = step ? job->step_size() : job->result_size();
  if (request->offset() < 0 || request->offset() > total_size) {
    return ToGrpcStatus(absl::OutOfRangeError(
        absl::StrCat("result: offset must be in [0, ", total_size, "] (the ",
                     step ? "STEP file" : "result", "'s size), got ", request->offset())));
  }
  const absl::StatusOr<std::unique_ptr<LocalBlob>> blob =
      blobs_.Open(step ? StepKey(job->job_id()) : ResultKey(job->job_id()));
  std::ifstream in;
  if (blob.ok()) in.open((*blob)->path(), std::ios::binary);
  if (in.is_open()) in.seekg(request->offset());
  if (!blob.ok() || !in.is_open()) {  // expired between Get() and here
    return ToGrpcStatus(absl::NotFoundError(
        absl::StrCat("result: job \"", job->job_id(), "\" result expired")));
  }
  const int chunk_bytes =
      request->chunk_size() == 0 ? kDefaultChunkBytes
                                 : std::min(request->chunk_size(), kMaxChunkBytes);
  std::vector<char> buffer(static_cast<std::size_t>(chunk_bytes));
  int64_t offset = request->offset();
  do {
    in.read(buffer.data(), chunk_bytes);
    const std::streamsize n = in.gcount();
    if (n == 0 && offset > request->offset()) break;
    v1::ResultChunk chunk;
    chunk.set_data(buffer.data(), static_cast<std::size_t>(n));
    chunk.set_offset(offset);
    chunk.set_total_size(total_size);
    if (context->IsCancelled() || !writer->Write(chunk)) {
      return ToGrpcStatus(absl::CancelledError("result: client went away"));
    }
    offset += n;
  } while (in);
  if (offset != total_size) {
    return ToGrpcStatus(absl::InternalError(absl::StrCat("result: job \"", job->job_id(), "\" ",
                                                         step ? "STEP file" : "result", " has ",
                                                         offset, " bytes, expected ", total_size)));
  }
  return grpc::Status::OK;
}

}  // namespace meshseg::server
