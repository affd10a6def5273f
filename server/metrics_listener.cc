#include "server/metrics_listener.h"

#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"

namespace meshseg::server {
namespace {

constexpr size_t kMaxRequestBytes = 8 << 10;
constexpr absl::Duration kRequestDeadline = absl::Seconds(5);

// Sends all of `data`; false if the peer went away or stalled past the send
// timeout.
bool SendAll(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = send(fd, data.data(), data.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

std::string Response(std::string_view status, std::string_view content_type,
                     std::string_view body, bool with_body, std::string_view extra = "") {
  return absl::StrCat("HTTP/1.1 ", std::string(status), "\r\nContent-Type: ",
                      std::string(content_type), "\r\nContent-Length: ", body.size(), "\r\n",
                      std::string(extra), "Connection: close\r\n\r\n",
                      with_body ? std::string(body) : std::string());
}

// Reads the request head (up to the blank line) within the deadline.
std::optional<std::string> ReadHead(int fd) {
  std::string head;
  const absl::Time deadline = absl::Now() + kRequestDeadline;
  char buffer[1024];
  while (head.find("\r\n\r\n") == std::string::npos && head.find("\n\n") == std::string::npos) {
    const int64_t left_ms = absl::ToInt64Milliseconds(deadline - absl::Now());
    pollfd p{fd, POLLIN, 0};
    if (left_ms <= 0 || poll(&p, 1, static_cast<int>(left_ms)) <= 0) return std::nullopt;
    const ssize_t n = recv(fd, buffer, sizeof(buffer), 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    head.append(buffer, static_cast<size_t>(n));
    if (head.size() > kMaxRequestBytes) return std::nullopt;
  }
  return head;
}

}  // namespace

absl::StatusOr<std::unique_ptr<MetricsListener>> MetricsListener::Start(
    const std::string& address, std::function<std::string()> body) {
  const size_t colon = address.rfind(':');
  int port = -1;
  if (colon == std::string::npos || !absl::SimpleAtoi(address.substr(colon + 1), &port) ||
      port < 0 || port > 65535) {
    return absl::InvalidArgumentError(
        absl::StrCat("--metrics-listen \"", address, "\": expected HOST:PORT, port 0-65535"));
  }
  std::string host = address.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string port_text = absl::StrCat(port);
  if (const int rc = getaddrinfo(host.empty() ? nullptr : host.c_str(), port_text.c_str(), &hints,
                                 &found);
      rc != 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("--metrics-listen \"", address, "\": ", gai_strerror(rc)));
  }
  const int fd = socket(found->ai_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int one = 1;
  if (fd >= 0) setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  const bool bound = fd >= 0 && bind(fd, found->ai_addr, found->ai_addrlen) == 0 &&
                     listen(fd, 16) == 0;
  const int error = errno;
  freeaddrinfo(found);
  if (!bound) {
    if (fd >= 0) close(fd);
    return absl::UnavailableError(absl::StrCat("--metrics-listen \"", address,
                                               "\": cannot listen: ", std::strerror(error)));
  }
  sockaddr_storage bound_address{};
  socklen_t length = sizeof(bound_address);
  getsockname(fd, reinterpret_cast<sockaddr*>(&bound_address), &length);
  const int bound_port = ntohs(bound_address.ss_family == AF_INET6
                                   ? reinterpret_cast<sockaddr_in6*>(&bound_address)->sin6_port
                                   : reinterpret_cast<sockaddr_in*>(&bound_address)->sin_port);
  const int wake = eventfd(0, EFD_CLOEXEC);
  if (wake < 0) {
    close(fd);
    return absl::UnavailableError(absl::StrCat("--metrics-listen: eventfd: ", std::strerror(errno)));
  }
  return std::unique_ptr<MetricsListener>(new MetricsListener(
      fd, wake, absl::StrCat(address.substr(0, colon), ":", bound_port), std::move(body)));
}

MetricsListener::MetricsListener(int listen_fd, int wake_fd, std::string address,
                                 std::function<std::string()> body)
    : listen_fd_(listen_fd), wake_fd_(wake_fd), address_(std::move(address)),
      body_(std::move(body)) {
  thread_ = std::thread([this] { Serve(); });
}

MetricsListener::~MetricsListener() {
  const uint64_t one = 1;
  (void)!write(wake_fd_, &one, sizeof(one));
  if (thread_.joinable()) thread_.join();
  close(listen_fd_);
  close(wake_fd_);
}

void MetricsListener::Serve() {
  while (true) {
    pollfd fds[2] = {{listen_fd_, POLLIN, 0}, {wake_fd_, POLLIN, 0}};
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    if (fds[1].revents != 0) return;
    const int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    const timeval send_timeout{5, 0};
    setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof(send_timeout));
    Answer(fd);
    // Lingering close: unread request bytes would make close() send a reset
    // that can overtake the response; read them (bounded) first.
    shutdown(fd, SHUT_WR);
    char drain[4096];
    for (int i = 0; i < 16; ++i) {
      pollfd p{fd, POLLIN, 0};
      if (poll(&p, 1, 100) <= 0 || recv(fd, drain, sizeof(drain), 0) <= 0) break;
    }
    close(fd);
  }
}

void MetricsListener::Answer(int fd) {
  constexpr std::string_view kText = "text/plain; charset=utf-8";
  const std::optional<std::string> head = ReadHead(fd);
  if (!head) {
    SendAll(fd, Response("400 Bad Request", kText, "bad or incomplete request\n", true));
    return;
  }
  const std::string_view line = std::string_view(*head).substr(0, head->find_first_of("\r\n"));
  const size_t first = line.find(' ');
  const size_t second = first == std::string_view::npos ? first : line.find(' ', first + 1);
  if (second == std::string_view::npos) {
    SendAll(fd, Response("400 Bad Request", kText, "bad request line\n", true));
    return;
  }
  const std::string_view method = line.substr(0, first);
  std::string_view path = line.substr(first + 1, second - first - 1);
  path = path.substr(0, path.find('?'));
  if (method != "GET" && method != "HEAD") {
    SendAll(fd, Response("405 Method Not Allowed", kText, "only GET and HEAD\n", true,
                         "Allow: GET, HEAD\r\n"));
    return;
  }
  if (path != "/metrics") {
    SendAll(fd, Response("404 Not Found", kText, "not found; metrics are at /metrics\n",
                         method == "GET"));
    return;
  }
  SendAll(fd, Response("200 OK", "text/plain; version=0.0.4; charset=utf-8", body_(),
                       method == "GET"));
}

}  // namespace meshseg::server
