#include "meshseg/proto/grpc_status.h"
#include "server/log.h"
#include "server/metrics.h"
#include "server/service.h"

namespace meshseg::server {

grpc::Status SegmentationService::CancelJob(grpc::ServerContext* context,
                                            const v1::CancelJobRequest* request,
                                            v1::Job* response) {
  const std::string& id = request->job_id();
  if (absl::StatusOr<v1::Job> own = OwnJob(*context, id); !own.ok()) {
    return ToGrpcStatus(own.status());
  }
  absl::StatusOr<JobStore::CancelOutcome> outcome = store_.Cancel(id, "cancelled by request");
  if (!outcome.ok()) return ToGrpcStatus(outcome.status());
  if (*outcome == JobStore::CancelOutcome::kWasQueued) {
    queue_.Remove(id);
    Metrics::Global().JobFinished("CANCELLED", std::nullopt);
    if (absl::StatusOr<v1::Job> job = store_.Get(id); job.ok()) {
      (void)blobs_.Remove(UploadKey(id, job->file_name()));
    }
  }
  Log("job_cancel_requested",
      {{"job", id},
       {"was", *outcome == JobStore::CancelOutcome::kWasQueued ? "QUEUED" : "RUNNING"}});
  absl::StatusOr<v1::Job> job = store_.Get(id);
  if (!job.ok()) return ToGrpcStatus(job.status());
  *response = *std::move(job);
  return grpc::Status::OK;
}

}  // namespace meshseg::server
