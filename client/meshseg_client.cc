#include "client/meshseg_client.h"

#include <filesystem>
#include <fstream>
#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/proto/credential_files.h"
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

MeshsegClient::MeshsegClient(std::shared_ptr<grpc::Channel> channel, std::string token)
    : stub_(v1::Segmentation::NewStub(channel)), token_(std::move(token)) {}

MeshsegClient MeshsegClient::Connect(const std::string& address) {
  return *Connect(address, ConnectOptions{});
}

absl::StatusOr<MeshsegClient> MeshsegClient::Connect(const std::string& address,
                                                     const ConnectOptions& options) {
  grpc::ChannelArguments args;
  args.SetMaxReceiveMessageSize(8 << 20);
  std::shared_ptr<grpc::ChannelCredentials> credentials = grpc::InsecureChannelCredentials();
  if (options.tls_cert.empty() != options.tls_key.empty()) {
    return absl::InvalidArgumentError("--tls-cert and --tls-key must be given together");
  }
  if (!options.tls_ca.empty()) {
    grpc::SslCredentialsOptions ssl;
    MESHSEG_ASSIGN_OR_RETURN(ssl.pem_root_certs, ReadCredentialFile(options.tls_ca, "--tls-ca"));
    if (!options.tls_cert.empty()) {
      MESHSEG_ASSIGN_OR_RETURN(ssl.pem_cert_chain,
                               ReadCredentialFile(options.tls_cert, "--tls-cert"));
      MESHSEG_ASSIGN_OR_RETURN(ssl.pem_private_key,
                               ReadCredentialFile(options.tls_key, "--tls-key"));
    }
    credentials = grpc::SslCredentials(ssl);
  } else if (!options.tls_cert.empty()) {
    return absl::InvalidArgumentError("--tls-cert needs --tls-ca (the server's CA)");
  }
  return MeshsegClient(grpc::CreateCustomChannel(address, credentials, args), options.token);
}

void MeshsegClient::Authorize(grpc::ClientContext& context) const {
  if (!token_.empty()) context.AddMetadata("authorization", absl::StrCat("Bearer ", token_));
}

std::unique_ptr<grpc::ClientContext> MeshsegClient::UnaryContext() const {
  auto context = std::make_unique<grpc::ClientContext>();
  context->set_deadline(absl::ToChronoTime(absl::Now() + call_timeout_));
  Authorize(*context);
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
  header->set_step(options.step);
  header->set_step_unit(options.step_unit);
  header->set_request_id(options.request_id);
  header->set_include_mesh(options.include_mesh);
  header->set_length_unit(options.length_unit);
  if (options.checksum) {
    MESHSEG_ASSIGN_OR_RETURN(*header->mutable_sha256(), FileSha256(path));
  }

  grpc::ClientContext context;
  Authorize(context);
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
  Authorize(context);
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

absl::StatusOr<std::string> MeshsegClient::ResultBytes(const std::string& job_id,
                                                       v1::ResultFormat format) {
  grpc::ClientContext context;
  Authorize(context);
  v1::GetResultRequest request;
  request.set_job_id(job_id);
  request.set_format(format);
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
  return bytes;
}

absl::StatusOr<v1::SegmentationResult> MeshsegClient::Result(const std::string& job_id) {
  MESHSEG_ASSIGN_OR_RETURN(const std::string bytes,
                           ResultBytes(job_id, v1::RESULT_FORMAT_UNSPECIFIED));
  v1::SegmentationResult result;
  if (!result.ParseFromString(bytes)) {
    return absl::DataLossError(
        absl::StrCat("result: job ", job_id, ": ", bytes.size(), " bytes do not parse"));
  }
  return result;
}

absl::Status MeshsegClient::SaveStep(const std::string& job_id, const std::string& path) {
  MESHSEG_ASSIGN_OR_RETURN(const std::string bytes, ResultBytes(job_id, v1::RESULT_FORMAT_STEP));
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    return absl::InternalError(absl::StrCat("step: cannot write \"", path, "\""));
  }
  return absl::OkStatus();
}

absl::StatusOr<v1::Job> MeshsegClient::GetJob(const std::string& job_id) {
  auto context = UnaryContext();
  v1::GetJobRequest request;
  request.set_job_id(job_id);
  v1::Job job;
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(stub_->GetJob(context.get(), request, &job)));
  return job;
}

absl::StatusOr<v1::ListJobsResponse> MeshsegClient::ListJobsPage(
    const v1::ListJobsRequest& request) {
  auto context = UnaryContext();
  v1::ListJobsResponse response;
  MESHSEG_RETURN_IF_ERROR(FromGrpcStatus(stub_->ListJobs(context.get(), request, &response)));
  return response;
}

absl::StatusOr<std::vector<v1::Job>> MeshsegClient::ListJobs() {
  std::vector<v1::Job> jobs;
  v1::ListJobsRequest request;
  request.set_page_size(1000);
  do {
    MESHSEG_ASSIGN_OR_RETURN(v1::ListJobsResponse page, ListJobsPage(request));
    for (v1::Job& job : *page.mutable_jobs()) jobs.push_back(std::move(job));
    request.set_page_token(page.next_page_token());
  } while (!request.page_token().empty());
  return jobs;
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
    const std::function<void(const v1::JobEvent&)>& on_event, v1::Job* job_out) {
  MESHSEG_ASSIGN_OR_RETURN(const v1::UploadResponse upload, Upload(path, options));
  MESHSEG_ASSIGN_OR_RETURN(const v1::Job job, Watch(upload.job_id(), on_event));
  if (job_out != nullptr) *job_out = job;
  if (job.state() != v1::JOB_STATE_SUCCEEDED) return JobError(job);
  return Result(upload.job_id());
}

}  // namespace meshseg
