#include "meshseg/proto/grpc_status.h"
#include "server/service.h"

namespace meshseg::server {

grpc::Status SegmentationService::ListJobs(grpc::ServerContext* /*context*/,
                                           const v1::ListJobsRequest* /*request*/,
                                           v1::ListJobsResponse* response) {
  absl::StatusOr<std::vector<v1::Job>> jobs = store_.List();
  if (!jobs.ok()) return ToGrpcStatus(jobs.status());
  for (v1::Job& job : *jobs) *response->add_jobs() = std::move(job);
  return grpc::Status::OK;
}

}  // namespace meshseg::server
