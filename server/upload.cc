#include <algorithm>
#include <filesystem>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/grpc_status.h"
#include "meshseg/status_macros.h"
#include "server/log.h"
#include "server/receive_upload.h"
#include "server/service.h"
#include "server/spool.h"

namespace meshseg::server {
namespace {

// Returns OK if the spooled file is in a format the pipeline reads: the
// hint if given, else by extension and content.
absl::Status CheckFormat(const std::string& path, const PipelineParams& params) {
  if (params.format.has_value()) return absl::OkStatus();
  absl::StatusOr<FileFormat> format = DetectFileFormat(path);
  if (!format.ok()) return absl::InvalidArgumentError(absl::StrCat("upload: ", format.status().message()));
  return absl::OkStatus();
}

}  // namespace

grpc::Status SegmentationService::Upload(grpc::ServerContext* context,
                                         grpc::ServerReader<v1::UploadRequest>* reader,
                                         v1::UploadResponse* response) {
  // The steps after the header, as one Status-returning function so each
  // failure path cleans up the same way.
  std::string job_id;
  std::string scratch;
  JobRecord record;
  const auto accept = [&]() -> absl::Status {
    if (!accepting_) return absl::UnavailableError("upload: server is shutting down");
    v1::UploadRequest first;
    if (!reader->Read(&first)) {
      return context->IsCancelled() ? absl::CancelledError("upload: client went away")
                                    : absl::InvalidArgumentError("upload: empty stream");
    }
    if (!first.has_header()) {
      return absl::InvalidArgumentError("upload: the first message must be the header");
    }
    const v1::UploadHeader& header = first.header();
    MESHSEG_RETURN_IF_ERROR(CheckUploadHeader(header, max_upload_bytes_));
    MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(header.options()));
    MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(header.format_hint()));
    // Refuse before receiving the data (also when the queue is unreachable).
    MESHSEG_ASSIGN_OR_RETURN(const int waiting, queue_.Size());
    if (waiting >= queue_.Capacity()) {
      return absl::ResourceExhaustedError(
          absl::StrCat("upload: job queue full (", queue_.Capacity(), " jobs waiting)"));
    }

    job_id = NewJobId();
    const std::string file_name = SafeFileName(header.file_name());
    scratch = scratch_.ScratchPath(job_id, file_name);
    MESHSEG_RETURN_IF_ERROR(ReceiveUpload(context, reader, header, max_upload_bytes_, scratch));
    MESHSEG_RETURN_IF_ERROR(CheckFormat(scratch, params));

    record.set_upload_key(UploadKey(job_id, file_name));
    MESHSEG_RETURN_IF_ERROR(blobs_.Put(record.upload_key(), scratch));
    v1::Job& job = *record.mutable_job();
    job.set_job_id(job_id);
    job.set_file_name(file_name);
    job.set_upload_size(header.total_size());
    job.set_created_unix_ms(absl::ToUnixMillis(absl::Now()));
    *record.mutable_options() = header.options();
    record.set_format_hint(header.format_hint());
    MESHSEG_RETURN_IF_ERROR(store_.Create(record));
    // Logged before the push: a free worker may log job_started at once.
    Log("job_queued", {{"job", job_id},
                       {"file", file_name},
                       {"bytes", absl::StrCat(header.total_size())},
                       {"peer", context->peer()}});
    if (absl::Status pushed = queue_.Push(job_id); !pushed.ok()) {
      store_.Remove(job_id);
      Log("job_dropped", {{"job", job_id}, {"error", std::string(pushed.message())}});
      return pushed;
    }
    response->set_job_id(job_id);
    response->set_queue_position(std::max(0, queue_.Position(job_id)));
    return absl::OkStatus();
  };

  const absl::Status status = accept();
  if (!status.ok()) {
    std::error_code ec;
    if (!scratch.empty()) std::filesystem::remove(scratch, ec);
    if (!record.upload_key().empty()) (void)blobs_.Remove(record.upload_key());
    Log("upload_rejected", {{"code", absl::StatusCodeToString(status.code())},
                            {"error", std::string(status.message())},
                            {"peer", context->peer()}});
  }
  return ToGrpcStatus(status);
}

}  // namespace meshseg::server
