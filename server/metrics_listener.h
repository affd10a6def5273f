// File: metrics_listener.h
// -----------------------------------------------------------------------------
// A minimal HTTP/1.1 listener for Prometheus scrapes (--metrics-listen
// HOST:PORT): GET or HEAD /metrics answers 200 with the body of a callback
// (text format 0.0.4); other paths 404, other methods 405. One thread, one
// request per connection (Connection: close), requests read with a 5 s
// deadline and capped at 8 KiB, so a slow or hostile client cannot hold the
// thread long or make it allocate. Apart from gRPC, so scrapes work on any
// role (workers have no gRPC service) and need no client certificate.
#ifndef MESHSEG_SERVER_METRICS_LISTENER_H_
#define MESHSEG_SERVER_METRICS_LISTENER_H_

#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "absl/status/statusor.h"

namespace meshseg::server {

class MetricsListener {
 public:
  // Listens on `address` ("HOST:PORT", "[::1]:PORT"; port 0 = ephemeral)
  // and serves `body()` for GET /metrics.
  // Errors: INVALID_ARGUMENT (no port, a host that does not resolve),
  // UNAVAILABLE (cannot bind or listen), each naming the address.
  static absl::StatusOr<std::unique_ptr<MetricsListener>> Start(
      const std::string& address, std::function<std::string()> body);

  // Stops serving and joins the thread.
  ~MetricsListener();
  MetricsListener(const MetricsListener&) = delete;
  MetricsListener& operator=(const MetricsListener&) = delete;

  // "HOST:PORT" with the port actually bound.
  const std::string& address() const { return address_; }

 private:
  MetricsListener(int listen_fd, int wake_fd, std::string address,
                  std::function<std::string()> body);
  void Serve();
  void Answer(int fd);

  const int listen_fd_;
  const int wake_fd_;  // an eventfd; written to stop Serve()
  const std::string address_;
  const std::function<std::string()> body_;
  std::thread thread_;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_METRICS_LISTENER_H_
