#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "meshseg/proto/grpc_status.h"
#include "server/service.h"

namespace meshseg::server {
namespace {

// How often a watcher with no news checks whether its client went away
// (the synchronous API has no callback for it).
constexpr absl::Duration kPollInterval = absl::Milliseconds(100);
// How often it reads the job although no change was signalled (a missed
// notification costs at most this much delay).
constexpr absl::Duration kRereadInterval = absl::Seconds(2);

bool SameEvent(const v1::Job& a, const v1::Job& b) {
  return a.state() == b.state() && a.queue_position() == b.queue_position() &&
         a.stage() == b.stage() && a.fraction() == b.fraction();
}

std::string Describe(const v1::Job& job) {
  switch (job.state()) {
    case v1::JOB_STATE_QUEUED:
      return absl::StrCat("queued, ", job.queue_position(), " ahead");
    case v1::JOB_STATE_RUNNING:
      return job.stage().empty() ? "running"
                                 : absl::StrFormat("%s %.0f%%", job.stage(),
                                                   100.0 * job.fraction());
    case v1::JOB_STATE_SUCCEEDED:
      return absl::StrCat("succeeded: ", job.region_count(), " regions, ", job.face_count(),
                          " faces");
    case v1::JOB_STATE_FAILED:
      return absl::StrCat("failed: ", job.error_message());
    case v1::JOB_STATE_CANCELLED:
      return absl::StrCat("cancelled: ", job.error_message());
    default:
      return "unknown state";
  }
}

}  // namespace

grpc::Status SegmentationService::WatchJob(grpc::ServerContext* context,
                                           const v1::WatchJobRequest* request,
                                           grpc::ServerWriter<v1::JobEvent>* writer) {
  const absl::StatusOr<std::unique_ptr<StreamLimit::Slot>> slot = StreamSlot("watch");
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  // Woken by this job's changes only (and, while it is queued, by the
  // queue moving), never by other jobs' progress; the store is read only
  // then (or rarely, as a safety net): in Redis mode a read is a round trip.
  const std::unique_ptr<JobChanges::Subscription> changes =
      store_.job_changes().Subscribe(request->job_id());
  v1::Job last;
  bool first = true;
  int64_t seen = 0;
  absl::Time next_read = absl::InfinitePast();
  while (true) {
    const int64_t version = changes->version();
    if (!first && version == seen && absl::Now() < next_read) {
      changes->Await(seen, kPollInterval);
      if (context->IsCancelled()) {
        return ToGrpcStatus(absl::CancelledError("watch: client went away or deadline passed"));
      }
      continue;
    }
    seen = version;
    next_read = absl::Now() + kRereadInterval;
    absl::StatusOr<v1::Job> job = OwnJob(*context, request->job_id());
    if (!job.ok()) return ToGrpcStatus(job.status());  // unknown, or expired meanwhile
    changes->set_queued(job->state() == v1::JOB_STATE_QUEUED);
    if (first || !SameEvent(*job, last)) {
      v1::JobEvent event;
      event.set_message(Describe(*job));
      *event.mutable_job() = *job;
      if (!writer->Write(event)) {
        return ToGrpcStatus(absl::CancelledError("watch: client went away"));
      }
      last = *std::move(job);
      first = false;
    }
    if (IsTerminal(last.state())) return grpc::Status::OK;
    changes->Await(seen, kPollInterval);
    if (context->IsCancelled()) {
      return ToGrpcStatus(absl::CancelledError("watch: client went away or deadline passed"));
    }
  }
}

}  // namespace meshseg::server
