// File: server.h
// -----------------------------------------------------------------------------
// meshseg-server as an object: the gRPC server with the Segmentation service
// (roles all and api), the standard health service, reflection if asked,
// the transport (TLS, mutual TLS, bearer tokens: credentials.h), the
// backend (job queue, job store, blob store, spool: embedded or Redis), the
// worker pool (roles all and worker) and the sweeper that forgets expired
// results.
// main.cc and the service tests both start it through this class.
#ifndef MESHSEG_SERVER_SERVER_H_
#define MESHSEG_SERVER_SERVER_H_

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "server/server_options.h"

namespace meshseg::server {

class Server {
 public:
  // Starts listening and the workers.
  // Errors: INVALID_ARGUMENT for bad options; FAILED_PRECONDITION if another
  // server holds the spool; INTERNAL if the spool cannot be set up;
  // UNAVAILABLE if the address cannot be bound.
  static absl::StatusOr<std::unique_ptr<Server>> Start(ServerOptions options);

  // Shuts down (as Shutdown()) if still running.
  ~Server();

  // The port actually bound (the ephemeral one for port 0).
  int port() const;
  // "HOST:PORT" with the bound port.
  std::string address() const;
  // Re-reads the --auth-tokens file (main.cc calls it on SIGHUP); on error
  // the old tokens stay in force. Returns the number of tokens now in force.
  // Errors: FAILED_PRECONDITION without --auth-tokens; those of
  // TokenAuth::Reload().
  absl::StatusOr<int> ReloadTokens();
  // Number of files in the spool (for tests and logs).
  int64_t SpoolFileCount() const;

  // Graceful shutdown: new uploads refused (UNAVAILABLE), the queue closed
  // (queued jobs stay queued: in the spool for the next start, or in Redis
  // for the other workers), then health NOT_SERVING (a client that sees
  // NOT_SERVING sees the first two done); running jobs are given
  // options.shutdown_grace to finish, then stopped and released (queued
  // again, the attempt not counted); then open calls end and the server
  // stops.
  void Shutdown();

  // Blocks until Shutdown() has completed.
  void Wait();

 private:
  struct Parts;
  explicit Server(std::unique_ptr<Parts> parts);
  std::unique_ptr<Parts> parts_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SERVER_H_
