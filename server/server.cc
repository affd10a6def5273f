#include "server/server.h"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/synchronization/notification.h"
#include "absl/time/clock.h"
#include "meshseg/status_macros.h"
#include "server/backend.h"
#include "server/log.h"
#include "server/service.h"
#include "server/worker_pool.h"

namespace meshseg::server {
namespace {

// Largest message the server accepts: an upload chunk is about 1 MiB.
constexpr int kMaxReceiveBytes = 8 << 20;
// Open calls (watchers) get this long to end after the jobs are done.
constexpr absl::Duration kCallDrainTime = absl::Seconds(2);

}  // namespace

struct Server::Parts {
  ServerOptions options;
  std::unique_ptr<Backend> backend;
  std::unique_ptr<SegmentationService> service;  // roles all and api
  std::unique_ptr<WorkerPool> workers;           // roles all and worker
  std::unique_ptr<grpc::Server> grpc_server;
  int port = 0;
  std::jthread sweeper;
  std::once_flag shutdown_once;
  absl::Notification shut_down;

  // Forgets finished jobs older than the result TTL, about once a second.
  void Sweep(std::stop_token stop) {
    std::mutex mu;
    std::condition_variable_any cv;
    const auto period = std::chrono::milliseconds(
        std::clamp<int64_t>(absl::ToInt64Milliseconds(options.result_ttl) / 4, 10, 1000));
    std::unique_lock<std::mutex> lock(mu);
    while (true) {
      // Wakes early only on stop; the predicate never holds.
      cv.wait_for(lock, stop, period, [] { return false; });
      if (stop.stop_requested()) return;
      for (const std::string& id : backend->store->Expire(absl::Now() - options.result_ttl)) {
        (void)backend->blobs->Remove(ResultKey(id));
        Log("job_expired", {{"job", id}});
      }
    }
  }
};

Server::Server(std::unique_ptr<Parts> parts) : parts_(std::move(parts)) {}

Server::~Server() {
  Shutdown();
  Wait();
}

absl::StatusOr<std::unique_ptr<Server>> Server::Start(ServerOptions options) {
  auto parts = std::make_unique<Parts>();
  MESHSEG_ASSIGN_OR_RETURN(parts->options, ResolveOptions(std::move(options)));
  const ServerOptions& o = parts->options;
  MESHSEG_ASSIGN_OR_RETURN(parts->backend, OpenBackend(o));
  Backend& b = *parts->backend;
  if (o.role != Role::kWorker) {
    parts->service = std::make_unique<SegmentationService>(*b.store, *b.queue, *b.blobs, *b.spool,
                                                           o.max_upload_bytes);
  }

  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  builder.AddListeningPort(o.listen, grpc::InsecureServerCredentials(), &parts->port);
  builder.SetMaxReceiveMessageSize(kMaxReceiveBytes);
  if (parts->service) builder.RegisterService(parts->service.get());
  parts->grpc_server = builder.BuildAndStart();
  if (!parts->grpc_server || parts->port == 0) {
    return absl::UnavailableError(absl::StrCat("server: cannot listen on \"", o.listen, "\""));
  }
  if (o.role != Role::kApi) {
    parts->workers = std::make_unique<WorkerPool>(o.workers, o.max_attempts, *b.queue, *b.store,
                                                  *b.blobs, *b.spool, o.runner);
  }
  Parts* p = parts.get();
  if (o.role != Role::kWorker) {
    parts->sweeper = std::jthread([p](std::stop_token stop) { p->Sweep(stop); });
  }
  Log("server_started", {{"listen", o.listen},
                         {"port", absl::StrCat(parts->port)},
                         {"role", RoleName(o.role)},
                         {"queue", o.queue.empty() ? "embedded" : o.queue},
                         {"workers", absl::StrCat(o.role == Role::kApi ? 0 : o.workers)},
                         {"queue_capacity", absl::StrCat(o.queue_capacity)},
                         {"spool", o.spool_dir}});
  return std::unique_ptr<Server>(new Server(std::move(parts)));
}

int Server::port() const { return parts_->port; }

std::string Server::address() const {
  const std::string& listen = parts_->options.listen;
  return absl::StrCat(listen.substr(0, listen.rfind(':')), ":", parts_->port);
}

int64_t Server::SpoolFileCount() const { return parts_->backend->spool->FileCount(); }

void Server::Shutdown() {
  std::call_once(parts_->shutdown_once, [this] {
    Parts& p = *parts_;
    Backend& b = *p.backend;
    Log("shutdown_started", {{"grace", absl::FormatDuration(p.options.shutdown_grace)}});
    // Health says NOT_SERVING last, so a client that sees it finds uploads
    // refused (the shutdown tests wait on it). Queued jobs stay queued: in
    // the spool for the next start, or in Redis for the other workers.
    if (p.service) p.service->StopAccepting();
    b.queue->Close();
    p.grpc_server->GetHealthCheckService()->SetServingStatus(false);
    if (p.workers) {
      if (!b.store->running().AwaitIdle(absl::Now() + p.options.shutdown_grace)) {
        Log("shutdown_releasing_running_jobs");
        b.store->running().StopAll(StopReason::kShutdown);
      }
      p.workers->GiveUpRetries();
      p.workers->Join();
    }
    p.grpc_server->Shutdown(absl::ToChronoTime(absl::Now() + kCallDrainTime));
    p.sweeper.request_stop();
    if (p.sweeper.joinable()) p.sweeper.join();
    Log("shutdown_done");
    p.shut_down.Notify();
  });
}

void Server::Wait() { parts_->shut_down.WaitForNotification(); }

}  // namespace meshseg::server
