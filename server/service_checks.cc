#include "absl/status/status.h"
#include "server/service.h"

namespace meshseg::server {

absl::StatusOr<std::string> SegmentationService::TenantOf(
    const grpc::ServerContext& context) const {
  if (auth_ == nullptr) return std::string();
  return auth_->TenantOf(context);
}

absl::StatusOr<v1::Job> SegmentationService::OwnJob(const grpc::ServerContext& context,
                                                    const std::string& id) const {
  absl::StatusOr<std::string> tenant = TenantOf(context);
  if (!tenant.ok()) return tenant.status();
  absl::StatusOr<v1::Job> job = store_.Get(id);
  if (!job.ok()) return job.status();
  if (job->tenant() != *tenant) return JobNotFound(id);
  return job;
}

absl::StatusOr<std::unique_ptr<StreamLimit::Slot>> SegmentationService::StreamSlot(
    absl::string_view call) const {
  if (admission_.streams == nullptr) return nullptr;
  return admission_.streams->Acquire(call);
}

}  // namespace meshseg::server
