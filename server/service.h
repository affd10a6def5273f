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

#include "meshseg/v1/service.grpc.pb.h"
#include "server/blob_store.h"
#include "server/job_queue.h"
#include "server/job_store.h"
#include "server/spool.h"

namespace meshseg::server {

class SegmentationService final : public v1::Segmentation::Service {
 public:
  // All references must outlive the service.
  // `scratch` holds uploads while they arrive, before they are put in `blobs`.
  SegmentationService(JobStore& store, JobQueue& queue, BlobStore& blobs, const Spool& scratch,
                      int64_t max_upload_bytes)
      : store_(store),
        queue_(queue),
        blobs_(blobs),
        scratch_(scratch),
        max_upload_bytes_(max_upload_bytes) {}

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
  const int64_t max_upload_bytes_;
  std::atomic<bool> accepting_ = true;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SERVICE_H_
