#include "meshseg/proto/grpc_status.h"
#include "server/service.h"

namespace meshseg::server {

grpc::Status SegmentationService::GetJob(grpc::ServerContext* context,
                                         const v1::GetJobRequest* request, v1::Job* response) {
  absl::StatusOr<v1::Job> job = OwnJob(*context, request->job_id());
  if (!job.ok()) return ToGrpcStatus(job.status());
  *response = *std::move(job);
  return grpc::Status::OK;
}

}  // namespace meshseg::server
