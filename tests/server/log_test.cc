// Structured log lines: `ts=<UTC time> event=<name> key=value ...`, one line
// per call on stderr, values quoted when they hold spaces, quotes or '=',
// whole lines even from many threads.
#include "server/log.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "scratch_dir.h"

namespace meshseg::server {
namespace {

using ::testing::ElementsAre;
using ::testing::MatchesRegex;

constexpr char kTime[] = "ts=[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}\\.[0-9]{3}Z";

// Returns what `write` puts on stderr (file descriptor 2), captured in the
// process's own scratch folder (scratch_dir.h).
template <typename Write>
std::string CaptureStderr(Write write) {
  const std::string path = testing_files::ScratchPath("captured.stderr");
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  FILE* file = std::fopen(path.c_str(), "w");
  EXPECT_NE(file, nullptr);
  dup2(fileno(file), STDERR_FILENO);
  write();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  std::fclose(file);
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::filesystem::remove(path);
  return text;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines = absl::StrSplit(text, '\n');
  EXPECT_EQ(lines.back(), "") << "every line ends in a newline";
  lines.pop_back();
  return lines;
}

TEST(Log, WritesOneLineWithTimeEventAndFieldsInOrder) {
  const std::string out = CaptureStderr([] {
    Log("job_started", {{"job", "job-0123abcd"}, {"input", "part.stl"}});
    Log("shutdown_done");
  });
  EXPECT_THAT(Lines(out),
              ElementsAre(MatchesRegex(absl::StrCat(kTime,
                                                    " event=job_started job=job-0123abcd "
                                                    "input=part\\.stl")),
                          MatchesRegex(absl::StrCat(kTime, " event=shutdown_done"))));
}

TEST(Log, QuotesValuesWithSpacesQuotesEqualsOrNewlinesAndKeepsOneLine) {
  const std::string out = CaptureStderr([] {
    Log("job_finished", {{"job", "job-1"},
                         {"state", "FAILED"},
                         {"error", "read_mesh: \"bad.obj\": nan\nat line 2"},
                         {"peer", "a=b"},
                         {"empty", ""},
                         {"path", "C:\\x y"}});
  });
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 1u) << out;
  EXPECT_THAT(lines[0], ::testing::EndsWith(" event=job_finished job=job-1 state=FAILED"
                                            " error=\"read_mesh: \\\"bad.obj\\\": nan\\nat line 2\""
                                            " peer=\"a=b\" empty=\"\" path=\"C:\\\\x y\""));
}

// An error message may quote bytes of an uploaded file: they reach the log
// escaped, so every line is valid UTF-8 and stays one line.
TEST(Log, EscapesBytesThatAreNotUtf8AndControlCharacters) {
  const std::string out = CaptureStderr([] {
    Log("upload_rejected", {{"error", "got \"\xff\xfe\r\""}, {"file", "a\tb"}});
  });
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 1u) << out;
  EXPECT_THAT(lines[0],
              ::testing::EndsWith(" error=\"got \\\"\\xff\\xfe\\x0d\\\"\" file=\"a\\x09b\""));
}

TEST(Log, LinesFromManyThreadsStayWhole) {
  constexpr int kThreads = 4;
  constexpr int kLines = 200;
  const std::string out = CaptureStderr([] {
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([t] {
        for (int i = 0; i < kLines; ++i) {
          Log("job_progress", {{"job", absl::StrCat("job-", t)}, {"n", absl::StrCat(i)}});
        }
      });
    }
    for (std::thread& t : threads) t.join();
  });
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kThreads * kLines));
  for (const std::string& line : lines) {
    ASSERT_THAT(line,
                MatchesRegex(absl::StrCat(kTime, " event=job_progress job=job-[0-9] n=[0-9]+")));
  }
}

}  // namespace
}  // namespace meshseg::server
