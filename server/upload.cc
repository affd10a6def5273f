#include <algorithm>
#include <filesystem>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "absl/time/clock.h"
#include "meshseg/input_size.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/grpc_status.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"
#include "server/log.h"
#include "server/metrics.h"
#include "server/receive_upload.h"
#include "server/service.h"
#include "server/spool.h"

namespace meshseg::server {
namespace {

// Returns OK if the spooled file is in a format the pipeline reads: the
// hint if given, else by extension and content.
// A volume's header is read here too: one file is uploaded, so a header
// whose samples are in another file (.mhd + .raw, detached NRRD) is refused
// now with what to send instead, not failed later in the job.
absl::Status CheckFormat(const std::string& path, const std::string& file_name,
                         const PipelineParams& params) {
  FileFormat format;
  if (params.format.has_value()) {
    format = *params.format;
  } else {
    absl::StatusOr<FileFormat> detected = DetectFileFormat(path);
    if (!detected.ok()) {
      return absl::InvalidArgumentError(absl::StrCat("upload: ", detected.status().message()));
    }
    format = *detected;
  }
  if (!IsVolumeFormat(format)) return absl::OkStatus();
  VolumeReadOptions read = params.volume.read;
  read.format = format;
  read.attached_data_only = true;
  absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path, read);
  if (!info.ok()) {  // the message names the spooled file: give the client's name
    return absl::InvalidArgumentError(absl::StrCat(
        "upload: ", absl::StrReplaceAll(info.status().message(),
                                        {{std::filesystem::path(path).filename().string(),
                                          file_name}})));
  }
  return absl::OkStatus();
}

// The header's raw_* fields (a headerless .raw volume's layout), kept in the
// job record for the worker.
void StoreRawLayout(const v1::UploadHeader& header, v1::UploadHeader* layout) {
  *layout->mutable_raw_dims() = header.raw_dims();
  *layout->mutable_raw_spacing() = header.raw_spacing();
  layout->set_raw_voxel_type(header.raw_voxel_type());
  *layout->mutable_raw_origin() = header.raw_origin();
  layout->set_raw_big_endian(header.raw_big_endian());
}

// Returns OK if the job in `path` can ever run under `budget` bytes (0 = not
// checked): its estimated peak (EstimateJobMemory, from the file's header
// or one pass over its lines) must fit the whole budget; a job that fits
// waits for room at its worker.
absl::Status CheckMemory(const std::string& path, const std::string& file_name,
                         const PipelineParams& params, int64_t budget) {
  if (budget == 0) return absl::OkStatus();
  absl::StatusOr<MemoryEstimate> estimate = EstimateJobMemory(path, params);
  if (!estimate.ok()) {  // the message names the spooled file: give the client's name
    return absl::InvalidArgumentError(absl::StrCat(
        "upload: ",
        absl::StrReplaceAll(estimate.status().message(),
                            {{std::filesystem::path(path).filename().string(), file_name}})));
  }
  if (estimate->peak_bytes <= budget) return absl::OkStatus();
  const InputSize& in = estimate->input;
  return absl::ResourceExhaustedError(absl::StrCat(
      "upload: \"", file_name, "\": ",
      in.point_cloud ? absl::StrCat(in.vertex_count, " points")
                     : absl::StrCat(in.face_count, " faces, ", in.vertex_count, " vertices"),
      " need an estimated ", estimate->peak_bytes >> 20, " MiB (", estimate->peak_bytes,
      " bytes) at peak, more than this server's whole memory budget of ", budget >> 20, " MiB (",
      budget, " bytes, --memory-budget)"));
}

// Returns OK for an empty request id or 1-128 printable ASCII characters.
absl::Status CheckRequestId(const std::string& id) {
  constexpr std::size_t kMaxLength = 128;
  const bool printable =
      std::all_of(id.begin(), id.end(), [](char c) { return c > 32 && c < 127; });
  if (id.size() <= kMaxLength && printable) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat("upload: request_id must be at most ", kMaxLength,
                                                 " printable ASCII characters without spaces, got ",
                                                 id.size(), " characters"));
}

// Returns OK if the header's length_unit and step_unit are known units that
// agree (StepUnitFromWire); the message names the field, value and units.
absl::Status CheckUnits(const v1::UploadHeader& header) {
  const absl::StatusOr<std::string> unit =
      StepUnitFromWire(header.step_unit(), header.length_unit());
  if (unit.ok()) return absl::OkStatus();
  return absl::Status(unit.status().code(), absl::StrCat("upload: ", unit.status().message()));
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
    MESHSEG_ASSIGN_OR_RETURN(const std::unique_ptr<StreamLimit::Slot> slot, StreamSlot("upload"));
    MESHSEG_ASSIGN_OR_RETURN(const std::string tenant, TenantOf(*context));
    v1::UploadRequest first;
    if (!reader->Read(&first)) {
      return context->IsCancelled() ? absl::CancelledError("upload: client went away")
                                    : absl::InvalidArgumentError("upload: empty stream");
    }
    if (!first.has_header()) {
      return absl::InvalidArgumentError("upload: the first message must be the header");
    }
    const v1::UploadHeader& header = first.header();
    MESHSEG_RETURN_IF_ERROR(CheckUploadHeader(header, admission_.max_upload_bytes));
    MESHSEG_RETURN_IF_ERROR(CheckRequestId(header.request_id()));
    MESHSEG_RETURN_IF_ERROR(CheckUnits(header));
    // A retry of an upload that created a job: answer with that job and
    // leave the data unread.
    MESHSEG_ASSIGN_OR_RETURN(const std::optional<std::string> earlier,
                             store_.FindRequest(tenant, header.request_id()));
    if (earlier.has_value()) {
      response->set_job_id(*earlier);
      response->set_queue_position(std::max(0, queue_.Position(*earlier)));
      Log("upload_repeated", {{"job", *earlier}, {"request_id", header.request_id()}});
      return absl::OkStatus();
    }
    MESHSEG_ASSIGN_OR_RETURN(PipelineParams params, FromProto(header.options()));
    MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(header.format_hint()));
    MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(header, &params));
    params.include_mesh = header.include_mesh();  // the estimate pays for the returned mesh
    // Refuse before receiving the data (also when the queue is unreachable).
    MESHSEG_ASSIGN_OR_RETURN(const int waiting, queue_.Size());
    if (waiting >= queue_.Capacity()) {
      return absl::ResourceExhaustedError(
          absl::StrCat("upload: job queue full (", queue_.Capacity(), " jobs waiting)"));
    }

    // The declared bytes are reserved on the disks they will occupy before
    // any is received; held until the upload is in the blob store or gone.
    std::unique_ptr<DiskReservations::Hold> disk;
    if (admission_.disk != nullptr) {
      MESHSEG_ASSIGN_OR_RETURN(disk, admission_.disk->Reserve(header.total_size()));
    }

    job_id = NewJobId();
    const std::string file_name = SafeFileName(header.file_name());
    scratch = scratch_.ScratchPath(job_id, file_name);
    MESHSEG_RETURN_IF_ERROR(
        ReceiveUpload(context, reader, header, admission_.max_upload_bytes, scratch));
    MESHSEG_RETURN_IF_ERROR(CheckFormat(scratch, file_name, params));
    MESHSEG_RETURN_IF_ERROR(CheckMemory(scratch, file_name, params, admission_.memory_budget));

    record.set_upload_key(UploadKey(job_id, file_name));
    MESHSEG_RETURN_IF_ERROR(blobs_.Put(record.upload_key(), scratch));
    v1::Job& job = *record.mutable_job();
    job.set_job_id(job_id);
    job.set_file_name(file_name);
    job.set_tenant(tenant);
    job.set_request_id(header.request_id());
    job.set_upload_size(header.total_size());
    job.set_created_unix_ms(absl::ToUnixMillis(absl::Now()));
    *record.mutable_options() = header.options();
    record.set_format_hint(header.format_hint());
    record.set_step(header.step());
    record.set_step_unit(header.step_unit());
    StoreRawLayout(header, record.mutable_raw_layout());
    record.set_include_mesh(header.include_mesh());
    record.set_length_unit(header.length_unit());
    MESHSEG_ASSIGN_OR_RETURN(const std::string created, store_.Create(record));
    if (created != job_id) {  // the same request completed meanwhile: its job stands
      (void)blobs_.Remove(record.upload_key());
      response->set_job_id(created);
      response->set_queue_position(std::max(0, queue_.Position(created)));
      Log("upload_repeated", {{"job", created}, {"request_id", header.request_id()}});
      return absl::OkStatus();
    }
    // Logged before the push: a free worker may log job_started at once.
    Log("job_queued", {{"job", job_id},
                       {"tenant", tenant},
                       {"file", file_name},
                       {"bytes", absl::StrCat(header.total_size())},
                       {"peer", context->peer()}});
    if (absl::Status pushed = queue_.Push(job_id); !pushed.ok()) {
      store_.Remove(job_id);
      Log("job_dropped", {{"job", job_id}, {"error", std::string(pushed.message())}});
      return pushed;
    }
    Metrics::Global().UploadAccepted(header.total_size());
    response->set_job_id(job_id);
    response->set_queue_position(std::max(0, queue_.Position(job_id)));
    return absl::OkStatus();
  };

  const absl::Status status = accept();
  if (!status.ok()) {
    std::error_code ec;
    if (!scratch.empty()) std::filesystem::remove(scratch, ec);
    if (!record.upload_key().empty()) (void)blobs_.Remove(record.upload_key());
    Metrics::Global().UploadRejected(status.code());
    Log("upload_rejected", {{"code", absl::StatusCodeToString(status.code())},
                            {"error", std::string(status.message())},
                            {"peer", context->peer()}});
  }
  return ToGrpcStatus(status);
}

}  // namespace meshseg::server
