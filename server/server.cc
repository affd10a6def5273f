#include "server/server.h"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/impl/server_builder_option.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/synchronization/notification.h"
#include "absl/time/clock.h"
#include "meshseg/status_macros.h"
#include "server/auth.h"
#include "server/backend.h"
#include "server/credentials.h"
#include "server/disk_reservations.h"
#include "server/memory_budget.h"
#include "server/stream_limit.h"
#include "server/log.h"
#include "server/metrics.h"
#include "server/metrics_listener.h"
#include "server/service.h"
#include "server/worker_pool.h"

namespace meshseg::server {
namespace {

// Largest message the server accepts: an upload chunk is about 1 MiB.
constexpr int kMaxReceiveBytes = 8 << 20;
// Open calls (watchers) get this long to end after the jobs are done.
constexpr absl::Duration kCallDrainTime = absl::Seconds(2);
// Threads of the synchronous server beyond the streaming-call cap, for
// unary calls and gRPC's own pollers.
constexpr int kSpareThreads = 64;

// Serves reflection on this server if `on`, else not. Linking
// libgrpc++_reflection registers its plugin for every server the process
// builds (a static initializer), so it is taken out of the builder's
// plugins here and added back only when asked for.
class ReflectionOption : public grpc::ServerBuilderOption {
 public:
  explicit ReflectionOption(bool on) : on_(on) {}
  void UpdateArguments(grpc::ChannelArguments* /*args*/) override {}
  void UpdatePlugins(std::vector<std::unique_ptr<grpc::ServerBuilderPlugin>>* plugins) override {
    auto reflection = std::make_unique<grpc::reflection::ProtoServerReflectionPlugin>();
    std::erase_if(*plugins, [&](const std::unique_ptr<grpc::ServerBuilderPlugin>& plugin) {
      return plugin->name() == reflection->name();
    });
    if (on_) plugins->push_back(std::move(reflection));
  }

 private:
  const bool on_;
};

}  // namespace

struct Server::Parts {
  ServerOptions options;
  std::unique_ptr<Backend> backend;
  std::unique_ptr<MetricsListener> metrics;  // --metrics-listen; reads the backend
  std::unique_ptr<MemoryBudget> memory;    // null: role api
  std::unique_ptr<DiskReservations> disk;  // roles all and api
  std::unique_ptr<StreamLimit> streams;
  std::unique_ptr<SegmentationService> service;  // roles all and api
  // Role worker: the service's base class, every method UNIMPLEMENTED. A
  // gRPC server needs one synchronous service to poll its health checks.
  std::unique_ptr<v1::Segmentation::Service> no_jobs_here;
  std::unique_ptr<WorkerPool> workers;           // roles all and worker
  std::unique_ptr<grpc::Server> grpc_server;
  std::shared_ptr<TokenAuth> auth;  // null without --auth-tokens
  std::string listen;               // as bound (credentials.h may move it to loopback)
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
        (void)backend->blobs->Remove(StepKey(id));
        Log("job_expired", {{"job", id}});
      }
    }
  }
};

Server::Server(std::unique_ptr<Parts> parts) : parts_(std::move(parts)) {}

Server::~Server() {
  Shutdown();
  Wait();
  parts_->metrics.reset();
  Metrics::Global().SetGauges({});  // they read the backend, about to go
}

absl::StatusOr<std::unique_ptr<Server>> Server::Start(ServerOptions options) {
  auto parts = std::make_unique<Parts>();
  MESHSEG_ASSIGN_OR_RETURN(parts->options, ResolveOptions(std::move(options)));
  const ServerOptions& o = parts->options;
  if (!o.security.auth_tokens.empty()) {
    MESHSEG_ASSIGN_OR_RETURN(parts->auth, TokenAuth::Load(o.security.auth_tokens));
  }
  MESHSEG_ASSIGN_OR_RETURN(const Transport transport,
                           BuildTransport(o.security, o.listen, parts->auth));
  parts->listen = transport.listen;
  MESHSEG_ASSIGN_OR_RETURN(parts->backend, OpenBackend(o));
  Backend& b = *parts->backend;
  parts->streams = std::make_unique<StreamLimit>(o.max_concurrent_streams);
  if (o.role != Role::kApi) parts->memory = std::make_unique<MemoryBudget>(o.memory_budget);
  if (o.role != Role::kWorker) {
    std::vector<std::string> upload_folders = {o.spool_dir};
    if (!o.blob_dir.empty()) upload_folders.push_back(o.blob_dir);
    parts->disk = std::make_unique<DiskReservations>(std::move(upload_folders), o.min_free_disk);
    const Admission admission = {.max_upload_bytes = o.max_upload_bytes,
                                 .memory_budget = o.memory_budget,
                                 .disk = parts->disk.get(),
                                 .streams = parts->streams.get()};
    parts->service = std::make_unique<SegmentationService>(*b.store, *b.queue, *b.blobs, *b.spool,
                                                           admission, parts->auth);
  }

  Metrics::Global().SetBuildInfo(RoleName(o.role), o.queue.empty() ? "embedded" : "redis");
  if (!o.metrics_listen.empty()) {
    MESHSEG_ASSIGN_OR_RETURN(parts->metrics, MetricsListener::Start(o.metrics_listen, [] {
                               return Metrics::Global().Exposition();
                             }));
    Log("metrics_listening", {{"address", parts->metrics->address()}});
  }

  grpc::EnableDefaultHealthCheckService(true);
  grpc::ServerBuilder builder;
  builder.AddListeningPort(transport.listen, transport.credentials, &parts->port);
  builder.SetMaxReceiveMessageSize(kMaxReceiveBytes);
  grpc::ResourceQuota quota("meshseg-server");
  quota.SetMaxThreads(o.max_concurrent_streams + kSpareThreads);
  builder.SetResourceQuota(quota);
  builder.SetOption(std::make_unique<ReflectionOption>(o.reflection));
  if (parts->service) {
    builder.RegisterService(parts->service.get());
  } else {
    parts->no_jobs_here = std::make_unique<v1::Segmentation::Service>();
    builder.RegisterService(parts->no_jobs_here.get());
  }
  parts->grpc_server = builder.BuildAndStart();
  if (!parts->grpc_server || parts->port == 0) {
    return absl::UnavailableError(
        absl::StrCat("server: cannot listen on \"", transport.listen, "\""));
  }
  if (!transport.note.empty()) Log("listen_loopback_only", {{"reason", transport.note}});
  if (o.role != Role::kApi) {
    parts->workers =
        std::make_unique<WorkerPool>(o.workers, o.max_attempts, *b.queue, *b.store, *b.blobs,
                                     *b.spool, o.runner, parts->memory.get());
  }
  Parts* p = parts.get();
  if (o.role != Role::kWorker) {
    parts->sweeper = std::jthread([p](std::stop_token stop) { p->Sweep(stop); });
  }
  // Set last: they read the backend, which lives as long as the server.
  Metrics::Global().SetGauges(
      {.queued = [&b]() -> std::optional<int64_t> {
         const absl::StatusOr<int> size = b.queue->Size();
         return size.ok() ? std::optional<int64_t>(*size) : std::nullopt;
       },
       .running = [&b] { return static_cast<int64_t>(b.store->running().Ids().size()); },
       .admission_reserved_bytes = [p = parts.get()]() -> int64_t {
         return p->memory ? p->memory->reserved() : 0;
       }});
  Log("server_started", {{"listen", transport.listen},
                         {"transport", transport.mode},
                         {"access", parts->auth ? "bearer" : "open"},
                         {"reflection", o.reflection ? "on" : "off"},
                         {"port", absl::StrCat(parts->port)},
                         {"role", RoleName(o.role)},
                         {"queue", o.queue.empty() ? "embedded" : o.queue},
                         {"workers", absl::StrCat(o.role == Role::kApi ? 0 : o.workers)},
                         {"queue_capacity", absl::StrCat(o.queue_capacity)},
                         {"memory_budget", absl::StrCat(o.memory_budget)},
                         {"max_concurrent_streams", absl::StrCat(o.max_concurrent_streams)},
                         {"spool", o.spool_dir}});
  return std::unique_ptr<Server>(new Server(std::move(parts)));
}

int Server::port() const { return parts_->port; }

std::string Server::address() const {
  const std::string& listen = parts_->listen;
  return absl::StrCat(listen.substr(0, listen.rfind(':')), ":", parts_->port);
}

absl::StatusOr<int> Server::ReloadTokens() {
  if (parts_->auth == nullptr) {
    return absl::FailedPreconditionError("tokens: the server runs without --auth-tokens");
  }
  absl::StatusOr<int> count = parts_->auth->Reload();
  if (count.ok()) {
    Log("tokens_reloaded", {{"count", absl::StrCat(*count)}});
  } else {
    Log("tokens_reload_failed", {{"error", std::string(count.status().message())}});
  }
  return count;
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
