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
  absl::StatusOr<v1::Job> job = store_.Get(request->job_id());
  if (!job.ok()) return ToGrpcStatus(job.status());
  if (absl::Status s = CheckSucceeded(*job); !s.ok()) return ToGrpcStatus(s);
  if (request->chunk_size() < 0) {
    return ToGrpcStatus(absl::InvalidArgumentError(
        absl::StrCat("result: chunk_size must be >= 0, got ", request->chunk_size())));
  }

  const absl::StatusOr<std::unique_ptr<LocalBlob>> blob = blobs_.Open(ResultKey(job->job_id()));
  std::ifstream in;
  if (blob.ok()) in.open((*blob)->path(), std::ios::binary);
  if (!blob.ok() || !in.is_open()) {  // expired between Get() and here
    return ToGrpcStatus(absl::NotFoundError(
        absl::StrCat("result: job \"", job->job_id(), "\" result expired")));
  }
  const int chunk_bytes =
      request->chunk_size() == 0 ? kDefaultChunkBytes
                                 : std::min(request->chunk_size(), kMaxChunkBytes);
  std::vector<char> buffer(static_cast<std::size_t>(chunk_bytes));
  int64_t offset = 0;
  do {
    in.read(buffer.data(), chunk_bytes);
    const std::streamsize n = in.gcount();
    if (n == 0 && offset > 0) break;
    v1::ResultChunk chunk;
    chunk.set_data(buffer.data(), static_cast<std::size_t>(n));
    chunk.set_offset(offset);
    chunk.set_total_size(job->result_size());
    if (context->IsCancelled() || !writer->Write(chunk)) {
      return ToGrpcStatus(absl::CancelledError("result: client went away"));
    }
    offset += n;
  } while (in);
  if (offset != job->result_size()) {
    return ToGrpcStatus(absl::InternalError(absl::StrCat(
        "result: job \"", job->job_id(), "\" result has ", offset, " bytes, expected ",
        job->result_size())));
  }
  return grpc::Status::OK;
}

}  // namespace meshseg::server
