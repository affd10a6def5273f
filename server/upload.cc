#include <algorithm>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "meshseg/mesh.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/grpc_status.h"
#include "meshseg/status_macros.h"
#include "server/log.h"
#include "server/receive_upload.h"
#include "server/service.h"

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
    MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(header, &params));
    if (queue_.Size() >= queue_.Capacity()) {  // refuse before receiving the data
      return absl::ResourceExhaustedError(
          absl::StrCat("upload: job queue full (", queue_.Capacity(), " jobs waiting)"));
    }

    job_id = store_.NewId();
    MESHSEG_ASSIGN_OR_RETURN(const std::string path, spool_.CreateJob(job_id, header.file_name()));
    MESHSEG_RETURN_IF_ERROR(ReceiveUpload(context, reader, header, max_upload_bytes_, path));
    MESHSEG_RETURN_IF_ERROR(CheckFormat(path, params));

    store_.Add(job_id, std::filesystem::path(path).filename().string(), header.total_size(),
               path, std::move(params));
    // Logged before the push: a free worker may log job_started at once.
    Log("job_queued", {{"job", job_id},
                       {"file", path.substr(path.find_last_of('/') + 1)},
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
    if (!job_id.empty()) spool_.RemoveJob(job_id);
    Log("upload_rejected", {{"code", absl::StatusCodeToString(status.code())},
                            {"error", std::string(status.message())},
                            {"peer", context->peer()}});
  }
  return ToGrpcStatus(status);
}

}  // namespace meshseg::server
