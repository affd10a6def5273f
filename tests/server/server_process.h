// The meshseg-server binary (MESHSEG_BIN_DIR) as a child process listening
// on 127.0.0.1:0: its bound address from the "listening on" line, its stderr
// (the structured log) collected as it arrives, signals, and a bounded wait
// for its exit. A child still running at the end is killed.
#ifndef MESHSEG_TESTS_SERVER_SERVER_PROCESS_H_
#define MESHSEG_TESTS_SERVER_SERVER_PROCESS_H_

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"

namespace meshseg::testing_server {

class ServerProcess {
 public:
  // Starts `meshseg-server --listen 127.0.0.1:0 flags...` with `env`
  // ("NAME=VALUE") added to the environment and waits up to 10 s for its
  // "listening on HOST:PORT" line (address() stays empty if none came).
  explicit ServerProcess(std::vector<std::string> flags, std::vector<std::string> env = {}) {
    flags.insert(flags.begin(),
                 {std::string(MESHSEG_BIN_DIR) + "/meshseg-server", "--listen", "127.0.0.1:0"});
    std::vector<char*> argv;
    for (std::string& f : flags) argv.push_back(f.data());
    argv.push_back(nullptr);
    for (char** e = environ; *e != nullptr; ++e) env.emplace_back(*e);
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    int out[2], err[2];
    if (pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {  // only async-signal-safe calls: the parent has threads
      dup2(out[1], STDOUT_FILENO);
      dup2(err[1], STDERR_FILENO);
      execve(argv[0], argv.data(), envp.data());
      _exit(127);
    }
    close(out[1]);
    close(err[1]);
    stdout_ = out[0];
    stderr_ = err[0];
    if (pid_ < 0) return;
    reader_ = std::thread([this] { ReadLog(); });
    first_line_ = ReadLine(stdout_, absl::Seconds(10));
    const std::string prefix = "listening on ";
    if (first_line_.rfind(prefix, 0) == 0) address_ = first_line_.substr(prefix.size());
  }

  ~ServerProcess() {
    if (pid_ > 0 && !exit_code_.has_value()) {
      kill(pid_, SIGKILL);
      int status = 0;
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    if (reader_.joinable()) reader_.join();
    if (stdout_ >= 0) close(stdout_);
    if (stderr_ >= 0) close(stderr_);
  }

  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  // "127.0.0.1:PORT", or empty if the server did not start.
  const std::string& address() const { return address_; }
  // The first line on stdout, without its '\n'.
  const std::string& first_line() const { return first_line_; }

  void Signal(int signal) const { kill(pid_, signal); }

  // kill -9, then reaps the process.
  void Kill9() {
    Signal(SIGKILL);
    AwaitExit(absl::Seconds(10));
  }

  // Everything written to stderr so far.
  std::string Log() const {
    absl::MutexLock lock(&mu_);
    return log_;
  }

  // Returns true once stderr holds `needle`; false after `timeout`.
  bool AwaitLog(const std::string& needle, absl::Duration timeout) const {
    absl::MutexLock lock(&mu_);
    const auto found = [&] { return log_.find(needle) != std::string::npos; };
    return mu_.AwaitWithTimeout(absl::Condition(&found), timeout);
  }

  // Returns the exit code (-1 if killed by a signal), or nullopt if the
  // process is still running after `timeout`.
  std::optional<int> AwaitExit(absl::Duration timeout) {
    const absl::Time deadline = absl::Now() + timeout;
    while (!exit_code_.has_value()) {
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      } else if (r < 0 && errno != EINTR) {
        return std::nullopt;
      } else if (absl::Now() > deadline) {
        return std::nullopt;
      } else {
        absl::SleepFor(absl::Milliseconds(5));
      }
    }
    return exit_code_;
  }

 private:
  // Collects stderr until the child closes it.
  void ReadLog() {
    char buf[4096];
    while (true) {
      const ssize_t n = read(stderr_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return;
      absl::MutexLock lock(&mu_);
      log_.append(buf, static_cast<std::size_t>(n));
    }
  }

  // Returns one line from `fd` (without '\n'), or what came before EOF or
  // `timeout`.
  static std::string ReadLine(int fd, absl::Duration timeout) {
    const absl::Time deadline = absl::Now() + timeout;
    std::string line;
    char c = 0;
    while (true) {
      pollfd p{.fd = fd, .events = POLLIN, .revents = 0};
      const int ms = static_cast<int>(absl::ToInt64Milliseconds(deadline - absl::Now()));
      if (ms <= 0 || poll(&p, 1, ms) <= 0) return line;
      if (read(fd, &c, 1) != 1 || c == '\n') return line;
      line.push_back(c);
    }
  }

  pid_t pid_ = -1;
  int stdout_ = -1;
  int stderr_ = -1;
  std::string first_line_;
  std::string address_;
  std::optional<int> exit_code_;
  std::thread reader_;
  mutable absl::Mutex mu_;
  std::string log_ ABSL_GUARDED_BY(mu_);
};

}  // namespace meshseg::testing_server

#endif  // MESHSEG_TESTS_SERVER_SERVER_PROCESS_H_
