#include "server/server.h"

#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>

#include "absl/strings/str_cat.h"
#include "absl/synchronization/notification.h"
#include "absl/time/clock.h"
#include "meshseg/status_macros.h"
#include "server/in_memory_job_queue.h"
#include "server/job_store.h"
#include "server/log.h"
#include "server/service.h"
#include "server/spool.h"
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
  std::optional<Spool> spool;
  std::unique_ptr<JobQueue> queue;
  std::unique_ptr<JobStore> store;
  std::unique_ptr<SegmentationService> service;
  std::unique_ptr<WorkerPool> workers;
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
      for (const std::string& id : store->Expire(absl::Now() - options.result_ttl)) {
        spool->RemoveJob(id);
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
  MESHSEG_ASSIGN_OR_RETURN(parts->spool, Spool::Open(o.spool_dir));
  parts->queue = std::make_unique<InMemoryJobQueue>(o.queue_capacity);
  parts->store = std::make_unique<JobStore>(*parts->queue);
  parts->service = std::make_unique<SegmentationService>(*parts->store, *parts->queue,
                                                         *parts->spool, o.max_upload_bytes);

  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  builder.AddListeningPort(o.listen, grpc::InsecureServerCredentials(), &parts->port);
  builder.SetMaxReceiveMessageSize(kMaxReceiveBytes);
  builder.RegisterService(parts->service.get());
  parts->grpc_server = builder.BuildAndStart();
  if (!parts->grpc_server || parts->port == 0) {
    return absl::UnavailableError(absl::StrCat("server: cannot listen on \"", o.listen, "\""));
  }
  parts->workers = std::make_unique<WorkerPool>(o.workers, *parts->queue, *parts->store,
                                                *parts->spool, o.runner);
  Parts* p = parts.get();
  parts->sweeper = std::jthread([p](std::stop_token stop) { p->Sweep(stop); });
  Log("server_started", {{"listen", o.listen},
                         {"port", absl::StrCat(parts->port)},
                         {"workers", absl::StrCat(o.workers)},
                         {"queue_capacity", absl::StrCat(o.queue_capacity)},
                         {"spool", o.spool_dir}});
  return std::unique_ptr<Server>(new Server(std::move(parts)));
}

int Server::port() const { return parts_->port; }

std::string Server::address() const {
  const std::string& listen = parts_->options.listen;
  return absl::StrCat(listen.substr(0, listen.rfind(':')), ":", parts_->port);
}

int64_t Server::SpoolFileCount() const { return parts_->spool->FileCount(); }

void Server::Shutdown() {
  std::call_once(parts_->shutdown_once, [this] {
    Parts& p = *parts_;
    Log("shutdown_started", {{"grace", absl::FormatDuration(p.options.shutdown_grace)}});
    // Health says NOT_SERVING last, so a client that sees it finds uploads
    // refused and the queue cancelled (the shutdown tests wait on it).
    p.service->StopAccepting();
    for (const std::string& id : p.queue->Close()) {
      if (p.store->Cancel(id, "server shutting down").ok()) {
        p.spool->RemoveJob(id);
        Log("job_cancelled", {{"job", id}, {"reason", "server shutting down"}});
      }
    }
    p.grpc_server->GetHealthCheckService()->SetServingStatus(false);
    if (!p.store->AwaitIdle(absl::Now() + p.options.shutdown_grace)) {
      Log("shutdown_cancelling_running_jobs");
      p.store->StopAll();
    }
    p.workers->Join();
    p.grpc_server->Shutdown(absl::ToChronoTime(absl::Now() + kCallDrainTime));
    p.sweeper.request_stop();
    if (p.sweeper.joinable()) p.sweeper.join();
    Log("shutdown_done");
    p.shut_down.Notify();
  });
}

void Server::Wait() { parts_->shut_down.WaitForNotification(); }

}  // namespace meshseg::server
