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
                         {"reason", ""},
                         {"file", "C:\\x y"}});
  });
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 1u) << out;
  EXPECT_THAT(lines[0], ::testing::EndsWith(" event=job_finished job=job-1 state=FAILED"
                                            " error=\"read_mesh: \\\"bad.obj\\\": nan\\nat line 2\""
                                            " peer=\"a=b\" reason=\"\" file=\"C:\\\\x y\""));
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
          Log("job_progress", {{"job", absl::StrCat("job-", t)}, {"count", absl::StrCat(i)}});
        }
      });
    }
    for (std::thread& t : threads) t.join();
  });
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kThreads * kLines));
  for (const std::string& line : lines) {
    ASSERT_THAT(line,
                MatchesRegex(absl::StrCat(kTime, " event=job_progress job=job-[0-9] count=[0-9]+")));
  }
}

constexpr char kAt[] = "2026-01-02T03:04:05.678Z";

TEST(Log, JsonLineHasTheFixedKeysFirstThenTheOtherFieldsAsStrings) {
  EXPECT_EQ(FormatLogLine(LogFormat::kJson, kAt, "job_finished",
                          {{"job", "job-1"}, {"state", "SUCCEEDED"}, {"seconds", "1.500"},
                           {"faces", "12"}}),
            "{\"time\":\"2026-01-02T03:04:05.678Z\",\"level\":\"info\",\"event\":\"job_finished\","
            "\"job_id\":\"job-1\",\"tenant\":\"\",\"stage\":\"\",\"duration\":1.5,"
            "\"state\":\"SUCCEEDED\",\"faces\":\"12\"}");
  EXPECT_EQ(FormatLogLine(LogFormat::kJson, kAt, "stage_done",
                          {{"job", "job-2"}, {"tenant", "acme"}, {"stage", "fit"}, {"seconds", "0.25"}}),
            "{\"time\":\"2026-01-02T03:04:05.678Z\",\"level\":\"info\",\"event\":\"stage_done\","
            "\"job_id\":\"job-2\",\"tenant\":\"acme\",\"stage\":\"fit\",\"duration\":0.25}");
}

TEST(Log, JsonLevelsMarkRefusedInputFailuresAndLostWork) {
  EXPECT_THAT(FormatLogLine(LogFormat::kJson, kAt, "upload_rejected", {{"code", "INVALID_ARGUMENT"}}),
              ::testing::HasSubstr("\"level\":\"warn\""));
  EXPECT_THAT(FormatLogLine(LogFormat::kJson, kAt, "job_finished", {{"state", "FAILED"}}),
              ::testing::HasSubstr("\"level\":\"warn\""));
  EXPECT_THAT(FormatLogLine(LogFormat::kJson, kAt, "job_finished", {{"state", "CANCELLED"}}),
              ::testing::HasSubstr("\"level\":\"info\""));
  EXPECT_THAT(FormatLogLine(LogFormat::kJson, kAt, "job_dropped", {{"error", "x"}}),
              ::testing::HasSubstr("\"level\":\"error\""));
}

TEST(Log, JsonEscapesQuotesControlsAndBytesThatAreNotUtf8) {
  // A value may quote an uploaded file: any bytes at all.
  const std::string value = std::string("a\"b\\c\nd\te\x01" "f\x7f") + "\xff\xfe\xc3" + "\xc3\xa9" +
                            "\xe2\x82\xac" + "\xed\xa0\x80";
  EXPECT_EQ(FormatLogLine(LogFormat::kJson, kAt, "upload_rejected", {{"error", value}}),
            "{\"time\":\"2026-01-02T03:04:05.678Z\",\"level\":\"warn\",\"event\":\"upload_rejected\","
            "\"job_id\":\"\",\"tenant\":\"\",\"stage\":\"\",\"duration\":null,"
            "\"error\":\"a\\\"b\\\\c\\nd\\te\\u0001f\\u007f\\u00ff\\u00fe\\u00c3\xc3\xa9\xe2\x82\xac"
            "\\u00ed\\u00a0\\u0080\"}")
      << "U+00E9 and U+20AC kept; a lone lead byte and an encoded surrogate escaped per byte";
}

TEST(Log, BearerCredentialsAreRedactedInEveryFormat) {
  for (const LogFormat format : {LogFormat::kText, LogFormat::kJson}) {
    const std::string line = FormatLogLine(
        format, kAt, "upload_rejected",
        {{"error", "refused: authorization: Bearer abcdefghijklmnop0123, BEARER\tqrstuvwxyz987654"}});
    EXPECT_THAT(line, ::testing::Not(::testing::HasSubstr("abcdefghijklmnop0123"))) << line;
    EXPECT_THAT(line, ::testing::Not(::testing::HasSubstr("qrstuvwxyz987654"))) << line;
    EXPECT_THAT(line, ::testing::HasSubstr("Bearer [redacted]")) << line;
  }
}

TEST(Log, RegisteredSecretsAreRedactedWhereverTheyAppear) {
  RegisterLogSecret("tok-Zq81x0PpLm33");
  RegisterLogSecret("short");  // too short to register: would blank ordinary words
  for (const LogFormat format : {LogFormat::kText, LogFormat::kJson}) {
    const std::string line =
        FormatLogLine(format, kAt, "upload_rejected",
                      {{"error", "file tok-Zq81x0PpLm33.stl is short"}, {"peer", "tok-Zq81x0PpLm33"}});
    EXPECT_THAT(line, ::testing::Not(::testing::HasSubstr("Zq81x0PpLm33"))) << line;
    EXPECT_THAT(line, ::testing::HasSubstr("[redacted].stl is short")) << line;
  }
}

TEST(Log, ParseLogFormatAcceptsTextAndJsonOnly) {
  EXPECT_EQ(*ParseLogFormat("text"), LogFormat::kText);
  EXPECT_EQ(*ParseLogFormat("json"), LogFormat::kJson);
  const absl::StatusOr<LogFormat> bad = ParseLogFormat("logfmt");
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad.status().message(), ::testing::HasSubstr("\"logfmt\""));
}

TEST(Log, EveryAllowedKeyIsDistinctAndNoneNamesACredential) {
  for (std::size_t i = 0; i < kLogKeys.size(); ++i) {
    for (std::size_t j = i + 1; j < kLogKeys.size(); ++j) EXPECT_NE(kLogKeys[i], kLogKeys[j]);
    for (const char* word : {"auth", "token", "secret", "password", "metadata", "header", "cookie",
                             "credential", "key", "cert"}) {
      EXPECT_EQ(kLogKeys[i].find(word), std::string_view::npos) << kLogKeys[i];
    }
  }
}

}  // namespace
}  // namespace meshseg::server
