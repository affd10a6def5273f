#include "absl/status/status.h"
#include "server/service.h"

namespace meshseg::server {

absl::StatusOr<std::string> SegmentationService::TenantOf(
    const grpc::ServerContext& context) const {
  if (auth_ == nullptr) return std::string();
  return auth_->TenantOf(context);
}

}  // namespace meshseg::server
