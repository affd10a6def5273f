#include "client/meshseg_client.h"

#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/grpc_status.h"
#include "meshseg/proto/sha256.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

absl::Status JobError(const v1::Job& job) {
  const auto code = job.error_code() != 0 ? static_cast<absl::StatusCode>(job.error_code())
                                          : absl::StatusCode::kUnknown;
  return absl::Status(code, job.error_message().empty()
                                ? absl::StrCat("job ", job.job_id(), " ",
                                               v1::JobState_Name(job.state()))
                                : job.error_message());
}

}  // namespace

MeshsegClient::MeshsegClient(std::shared_ptr<grpc::Channel> channel)
    : stub_(v1::Segmentation::NewStub(channel)) {}

MeshsegClient MeshsegClient::Connect(const std::string& address) {
  grpc::ChannelArguments args;
  args.SetMaxReceiveMessageSize(8 << 20);
  return MeshsegClient(
      grpc::CreateCustomChannel(address, grpc::InsecureChannelCredentials(), args));
}

std::unique_ptr<grpc::ClientContext> MeshsegClient::UnaryContext() const {
  auto context = std::make_unique<grpc::ClientContext>();
  context->set_deadline(absl::ToChronoTime(absl::Now() + call_timeout_));
  return context;
}

absl::StatusOr<v1::UploadResponse> MeshsegClient::Upload(const std::string& path,
                                                         const UploadOptions& options) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return absl::NotFoundError(absl::StrCat("upload: cannot read \"", path, "\""));

  v1::UploadRequest request;
  v1::UploadHeader* header = request.mutable_header();
  header->MergeFrom(options.raw);
  header->set_file_name(std::filesystem::path(path).filename().string());
  header->set_format_hint(options.format_hint);
  header->set_total_size(static_cast<int64_t>(size));
  *header->mutable_options() = options.segment;
  if (options.checksum) {
    MESHSEG_ASSIGN_OR_RETURN(*header->mutable_sha256(), FileSha256(path));
  }

  grpc::ClientContext context;
  v1::UploadResponse response;
  std::unique_ptr<grpc::ClientWriter<v1::UploadRequest>> writer =
      stub_->Upload(&context, &response);
  bool open = writer->Write(request);
  std::string buffer(options.chunk_bytes, '\0');
  while (open && in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize n = in.gcount();
    if (n <= 0) break;
    request.set_chunk(buffer.data(), static_cast<std::size_t>(n));
    open = writer->Write(request);
  }
  if (open) writer->WritesDone();
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(writer->Finish()));
  return response;
}

absl::StatusOr<v1::Job> MeshsegClient::Watch(
    const std::string& job_id, const std::function<void(const v1::JobEvent&)>& on_event,
    absl::Duration timeout) {
  grpc::ClientContext context;
  if (timeout != absl::InfiniteDuration()) {
    context.set_deadline(absl::ToChronoTime(absl::Now() + timeout));
  }
  v1::WatchJobRequest request;
  request.set_job_id(job_id);
  auto reader = stub_->WatchJob(&context, request);
  v1::JobEvent event;
  v1::Job last;
  while (reader->Read(&event)) {
    if (on_event) on_event(event);
    last = event.job();
  }
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(reader->Finish()));
  if (last.job_id().empty()) {
    return absl::InternalError(absl::StrCat("watch: no event for job ", job_id));
  }
  return last;
}

absl::StatusOr<v1::SegmentationResult> MeshsegClient::Result(const std::string& job_id) {
  grpc::ClientContext context;
  v1::GetResultRequest request;
  request.set_job_id(job_id);
  auto reader = stub_->GetResult(&context, request);
  std::string bytes;
  v1::ResultChunk chunk;
  while (reader->Read(&chunk)) {
    if (chunk.offset() != static_cast<int64_t>(bytes.size())) {
      context.TryCancel();
      reader->Finish();
      return absl::DataLossError(absl::StrCat("result: chunk at offset ", chunk.offset(),
                                              ", expected ", bytes.size()));
    }
    if (bytes.empty()) bytes.reserve(static_cast<std::size_t>(chunk.total_size()));
    bytes += chunk.data();
  }
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(reader->Finish()));
  v1::SegmentationResult result;
  if (!result.ParseFromString(bytes)) {
    return absl::DataLossError(
        absl::StrCat("result: job ", job_id, ": ", bytes.size(), " bytes do not parse"));
  }
  return result;
}

absl::StatusOr<v1::Job> MeshsegClient::GetJob(const std::string& job_id) {
  auto context = UnaryContext();
  v1::GetJobRequest request;
  request.set_job_id(job_id);
  v1::Job job;
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(stub_->GetJob(context.get(), request, &job)));
  return job;
}

absl::StatusOr<std::vector<v1::Job>> MeshsegClient::ListJobs() {
  auto context = UnaryContext();
  v1::ListJobsResponse response;
  MESHSEG_RETURN_IF_ERROR(
      FromGrpcStatus(stub_->ListJobs(context.get(), v1::ListJobsRequest(), &response)));
  return std::vector<v1::Job>(response.jobs().begin(), response.jobs().end());
}

absl::StatusOr<v1::Job> MeshsegClient::Cancel(const std::string& job_id) {
  auto context = UnaryContext();
  v1::CancelJobRequest request;
  request.set_job_id(job_id);
  v1::Job job;
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(stub_->CancelJob(context.get(), request, &job)));
  return job;
}

absl::StatusOr<v1::SegmentationResult> MeshsegClient::Segment(
    const std::string& path, const UploadOptions& options,
    const std::function<void(const v1::JobEvent&)>& on_event) {
  MESHSEG_ASSIGN_OR_RETURN(const v1::UploadResponse upload, Upload(path, options));
  MESHSEG_ASSIGN_OR_RETURN(const v1::Job job, Watch(upload.job_id(), on_event));
  if (job.state() != v1::JOB_STATE_SUCCEEDED) return JobError(job);
  return Result(upload.job_id());
}

}  // namespace meshseg
