#include "server/service.h"

namespace meshseg::server {

grpc::Status SegmentationService::ListJobs(grpc::ServerContext* /*context*/,
                                           const v1::ListJobsRequest* /*request*/,
                                           v1::ListJobsResponse* response) {
  for (v1::Job& job : store_.List()) *response->add_jobs() = std::move(job);
  return grpc::Status::OK;
}

}  // namespace meshseg::server
