// A real redis-server (Debian's package) as a child process for the Redis
// mode tests: loopback only, a free port, its own folder, AOF on (as the
// deployment runs it), no RDB snapshots. Restart() starts it again on the
// same port and folder, so it reloads its AOF (the kill -9 tests).
#ifndef MESHSEG_TESTS_SERVER_REDIS_PROCESS_H_
#define MESHSEG_TESTS_SERVER_REDIS_PROCESS_H_

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "server/redis_connection.h"

namespace meshseg::testing_server {

// Returns a loopback port that was free a moment ago (bound to port 0 and
// released); the caller retries if another process takes it meanwhile.
inline int FreePort() {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  socklen_t len = sizeof addr;
  int port = 0;
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
      getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0) {
    port = ntohs(addr.sin_port);
  }
  close(fd);
  return port;
}

class RedisProcess {
 public:
  // Starts redis-server with its data in `dir`; ok() says whether it
  // answers PING within 10 s (three ports are tried).
  explicit RedisProcess(std::string dir) : dir_(std::move(dir)) {
    for (int tries = 0; tries < 3 && !ok_; ++tries) {
      port_ = FreePort();
      ok_ = Launch();
    }
  }
  ~RedisProcess() { Kill9(); }
  RedisProcess(const RedisProcess&) = delete;
  RedisProcess& operator=(const RedisProcess&) = delete;

  bool ok() const { return ok_; }
  int port() const { return port_; }
  std::string url() const { return absl::StrCat("redis://127.0.0.1:", port_); }

  // kill -9 and reap.
  void Kill9() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
  }

  // Starts it again on the same port and folder (it reloads the AOF).
  bool Restart() {
    Kill9();
    ok_ = Launch();
    return ok_;
  }

 private:
  bool Launch() {
    std::vector<std::string> args = {"/usr/bin/redis-server",
                                     "--port",
                                     absl::StrCat(port_),
                                     "--bind",
                                     "127.0.0.1",
                                     "--dir",
                                     dir_,
                                     "--appendonly",
                                     "yes",
                                     "--save",
                                     "",
                                     "--daemonize",
                                     "no",
                                     "--logfile",
                                     dir_ + "/redis.log",
                                     "--protected-mode",
                                     "yes"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      execv(argv[0], argv.data());
      _exit(127);
    }
    if (pid_ < 0) return false;
    server::RedisConnection ping(
        server::RedisAddress{.host = "127.0.0.1", .port = port_, .db = 0, .text = "test"},
        absl::Seconds(1));
    const absl::Time deadline = absl::Now() + absl::Seconds(10);
    while (absl::Now() < deadline) {
      absl::StatusOr<server::RedisValue> pong = ping.Command({"PING"});
      if (pong.ok() && pong->str == "PONG") return true;
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {  // exited: port taken?
        pid_ = -1;
        return false;
      }
      absl::SleepFor(absl::Milliseconds(20));
    }
    return false;
  }

  std::string dir_;
  int port_ = 0;
  pid_t pid_ = -1;
  bool ok_ = false;
};

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_REDIS_PROCESS_H_
