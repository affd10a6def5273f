// File: service.h
// -----------------------------------------------------------------------------
// The meshseg.v1.Segmentation service (proto/meshseg/v1/service.proto) on
// gRPC's synchronous API. Each RPC is defined in its own file (upload.cc,
// watch_job.cc, get_result.cc, get_job.cc, list_jobs.cc, cancel_job.cc);
// streaming handlers poll ServerContext::IsCancelled() so a client that goes
// away or a passed deadline ends them.
#ifndef MESHSEG_SERVER_SERVICE_H_
#define MESHSEG_SERVER_SERVICE_H_

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "meshseg/v1/service.grpc.pb.h"
#include "server/auth.h"
#include "server/blob_store.h"
#include "server/disk_reservations.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/spool.h"
#include "server/stream_limit.h"

namespace meshseg::server {

// What an upload must fit before it is accepted.
struct Admission {
  // Max bytes of one upload.
  int64_t max_upload_bytes = 0;
  // A job whose estimated peak memory exceeds this is refused; 0 = not
  // checked here.
  int64_t memory_budget = 0;
  // Free disk reserved for uploads in flight; null = not reserved.
  DiskReservations* disk = nullptr;
  // Server-wide cap on open streaming calls; null = none.
  StreamLimit* streams = nullptr;
};

class SegmentationService final : public v1::Segmentation::Service {
 public:
  // All references must outlive the service.
  // `scratch` holds uploads while they arrive, before they are put in `blobs`.
  // `auth` (null: no authentication, every caller is the tenant "") says
  // which tenant a call comes from.
  SegmentationService(JobStore& store, JobQueue& queue, BlobStore& blobs, const Spool& scratch,
                      Admission admission, std::shared_ptr<const TokenAuth> auth = nullptr)
      : store_(store),
        queue_(queue),
        blobs_(blobs),
        scratch_(scratch),
        admission_(admission),
        auth_(std::move(auth)) {}

  // From now on Upload answers UNAVAILABLE (shutting down).
  void StopAccepting() { accepting_ = false; }

  grpc::Status Upload(grpc::ServerContext* context,
                      grpc::ServerReader<v1::UploadRequest>* reader,
                      v1::UploadResponse* response) override;
  grpc::Status WatchJob(grpc::ServerContext* context, const v1::WatchJobRequest* request,
                        grpc::ServerWriter<v1::JobEvent>* writer) override;
  grpc::Status GetResult(grpc::ServerContext* context, const v1::GetResultRequest* request,
                         grpc::ServerWriter<v1::ResultChunk>* writer) override;
  grpc::Status GetJob(grpc::ServerContext* context, const v1::GetJobRequest* request,
                      v1::Job* response) override;
  grpc::Status ListJobs(grpc::ServerContext* context, const v1::ListJobsRequest* request,
                        v1::ListJobsResponse* response) override;
  grpc::Status CancelJob(grpc::ServerContext* context, const v1::CancelJobRequest* request,
                         v1::Job* response) override;

 private:
  JobStore& store_;
  JobQueue& queue_;
  BlobStore& blobs_;
  const Spool& scratch_;
  // Returns the caller's tenant ("" without --auth-tokens).
  // Errors: UNAUTHENTICATED (the auth processor let no such call through).
  absl::StatusOr<std::string> TenantOf(const grpc::ServerContext& context) const;
  // Returns job `id` if it belongs to the caller's tenant. Errors: NOT_FOUND
  // for another tenant's job, with the message of an unknown id; those of
  // TenantOf and JobStore::Get.
  absl::StatusOr<v1::Job> OwnJob(const grpc::ServerContext& context, const std::string& id) const;

  // Returns a slot of the streaming-call cap (null when there is none).
  // Errors: RESOURCE_EXHAUSTED when every slot is taken.
  absl::StatusOr<std::unique_ptr<StreamLimit::Slot>> StreamSlot(absl::string_view call) const;

  const Admission admission_;
  const std::shared_ptr<const TokenAuth> auth_;
  std::atomic<bool> accepting_ = true;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SERVICE_H_
