// Runs the real `meshseg` binary (build/bin/meshseg) as a subprocess for the
// CLI tests: with stdout and stderr captured separately (a pipe and a file,
// neither a terminal), or on a pseudo-terminal (stdout and stderr both it).
#ifndef MESHSEG_TESTS_CLIENT_RUN_CLI_H_
#define MESHSEG_TESTS_CLIENT_RUN_CLI_H_

#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "tests/server/test_files.h"

namespace meshseg::testing_cli {

inline const std::string kMeshseg = std::string(MESHSEG_BIN_DIR) + "/meshseg";

struct CliRun {
  int exit_code = -1;  // -1: did not exit normally
  std::string out;
  std::string err;
};

namespace internal {

inline std::vector<char*> Argv(std::vector<std::string>& args) {
  args.insert(args.begin(), kMeshseg);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

// The environment without MESHSEG_SERVER (built before fork: the child of a
// threaded process may only make async-signal-safe calls).
inline std::vector<char*> Environment() {
  std::vector<char*> env;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::string(*e).rfind("MESHSEG_SERVER=", 0) != 0) env.push_back(*e);
  }
  env.push_back(nullptr);
  return env;
}

inline int ExitCode(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace internal

// Called with everything the command has written to stdout (or the
// terminal) so far, each time more arrives.
using OnOutput = std::function<void(const std::string& so_far)>;

namespace internal {

// Reads `fd` to its end (EOF, or EIO from a closed pseudo-terminal).
inline std::string ReadAll(int fd, const OnOutput& on_output) {
  std::string text;
  char buf[4096];
  while (true) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) {
      text.append(buf, static_cast<std::size_t>(n));
      if (on_output) on_output(text);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      return text;
    }
  }
}

}  // namespace internal

// Runs `meshseg args...` with stdout on a pipe and stderr in a file (neither
// a terminal), stdin /dev/null and $MESHSEG_SERVER unset.
inline CliRun RunCli(std::vector<std::string> args, const OnOutput& on_output = {}) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string err_path = testing_files::ScratchPath(std::string(info->test_suite_name()) +
                                                          "_" + info->name() + ".stderr");
  std::vector<char*> argv = internal::Argv(args);
  std::vector<char*> env = internal::Environment();
  int out[2];
  if (pipe(out) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    const int in = open("/dev/null", O_RDONLY);
    const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || err < 0) _exit(126);
    dup2(in, STDIN_FILENO);
    dup2(out[1], STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    close(out[0]);
    close(out[1]);
    execve(argv[0], argv.data(), env.data());
    _exit(127);
  }
  close(out[1]);
  CliRun run;
  if (pid < 0) {
    close(out[0]);
    return run;
  }
  run.out = internal::ReadAll(out[0], on_output);
  close(out[0]);
  run.exit_code = internal::ExitCode(pid);
  run.err = testing_files::ReadText(err_path);
  return run;
}

// Runs `meshseg args...` with stdout and stderr on one pseudo-terminal and
// returns everything it wrote there in `out`.
inline CliRun RunCliOnTerminal(std::vector<std::string> args, const OnOutput& on_output = {}) {
  std::vector<char*> argv = internal::Argv(args);
  std::vector<char*> env = internal::Environment();
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    execve(argv[0], argv.data(), env.data());
    _exit(127);
  }
  CliRun run;
  if (pid < 0) return run;
  run.out = internal::ReadAll(master, on_output);
  close(master);
  run.exit_code = internal::ExitCode(pid);
  return run;
}

// Returns `json` parsed into a Struct; fails the test if it is not JSON.
inline google::protobuf::Struct ParseJsonObject(const std::string& json) {
  google::protobuf::Struct s;
  const auto status = google::protobuf::util::JsonStringToMessage(json, &s);
  EXPECT_TRUE(status.ok()) << status.ToString() << "\n" << json.substr(0, 400);
  return s;
}

// Returns the lines of `text` (without their '\n').
inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

}  // namespace meshseg::testing_cli

#endif  // MESHSEG_TESTS_CLIENT_RUN_CLI_H_
