// The meshseg-server binary: prints the bound address, stops on SIGTERM with
// exit code 0, and refuses bad flags with one line.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

const std::string kServer = std::string(MESHSEG_BIN_DIR) + "/meshseg-server";

TEST(ServerMain, PrintsTheBoundPortAndStopsOnSigterm) {
  const std::string spool = std::string(::testing::TempDir()) + "/server_main_spool";
  int out[2];
  ASSERT_EQ(pipe(out), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    execl(kServer.c_str(), kServer.c_str(), "--listen", "127.0.0.1:0", "--spool-dir",
          spool.c_str(), "--workers", "1", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  FILE* in = fdopen(out[0], "r");
  char line[256] = {};
  ASSERT_NE(fgets(line, sizeof line, in), nullptr);
  EXPECT_THAT(std::string(line), ::testing::MatchesRegex("listening on 127\\.0\\.0\\.1:[0-9]+\n"));
  EXPECT_NE(std::string(line), "listening on 127.0.0.1:0\n");
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  fclose(in);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(ServerMain, BadFlagValueExitsNonZero) {
  const std::string cmd = kServer + " --listen 127.0.0.1:0 --queue-capacity 0 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string output;
  char buf[256];
  while (fgets(buf, sizeof buf, p)) output += buf;
  const int status = pclose(p);
  EXPECT_NE(WEXITSTATUS(status), 0);
  EXPECT_THAT(output, ::testing::HasSubstr("--queue-capacity"));
}

}  // namespace
