#include "meshseg/proto/grpc_status.h"

#include <string>

#include <gtest/gtest.h>

namespace meshseg {
namespace {

TEST(ToGrpcStatus, MapsEveryCodeOneToOne) {
  for (int code = 0; code <= 16; ++code) {
    const absl::Status s(static_cast<absl::StatusCode>(code), code ? "boom" : "");
    const grpc::Status g = ToGrpcStatus(s);
    EXPECT_EQ(static_cast<int>(g.error_code()), code);
    EXPECT_EQ(FromGrpcStatus(g).code(), s.code());
  }
}

TEST(ToGrpcStatus, CutsLongMessagesAtOneKibibyte) {
  const grpc::Status g = ToGrpcStatus(absl::InvalidArgumentError(std::string(5000, 'x')));
  EXPECT_EQ(g.error_message().size(), kMaxStatusMessageBytes);
}

TEST(ToGrpcStatus, CutsOnACharacterBoundary) {
  // 1023 ASCII bytes then a 2-byte character straddling the limit.
  const std::string message = std::string(1023, 'a') + "\xC3\xA9" + "tail";
  const grpc::Status g = ToGrpcStatus(absl::InternalError(message));
  EXPECT_EQ(g.error_message(), std::string(1023, 'a'));
}

// The reader's message for the 11-byte file `OFF\n\xff\xfe 3 0\n` quotes the
// token it could not parse; the bytes must reach the client escaped.
TEST(ToGrpcStatus, EscapesFileBytesThatAreNotUtf8) {
  const grpc::Status g = ToGrpcStatus(absl::InvalidArgumentError(
      "read_mesh: \"a.off\": line 2: expected the vertex count, got \"\xff\xfe\""));
  EXPECT_EQ(g.error_message(),
            "read_mesh: \"a.off\": line 2: expected the vertex count, got \"\\xff\\xfe\"");
}

TEST(SetJobError, StoresCodeAndAMessageThatSerializesAndParses) {
  v1::Job job;
  job.set_job_id("job-1");
  SetJobError(absl::InvalidArgumentError(std::string("bad \xff\xfe\n") + std::string(2000, 'z')),
              &job);
  EXPECT_EQ(job.error_code(), static_cast<int>(absl::StatusCode::kInvalidArgument));
  EXPECT_EQ(job.error_message().substr(0, 16), "bad \\xff\\xfe\\x0a");
  EXPECT_LE(job.error_message().size(), kMaxStatusMessageBytes);
  // A Job with raw non-UTF-8 bytes fails to parse on the client (proto3
  // strings); the escaped one round-trips.
  v1::Job parsed;
  ASSERT_TRUE(parsed.ParseFromString(job.SerializeAsString()));
  EXPECT_EQ(parsed.error_message(), job.error_message());
}

}  // namespace
}  // namespace meshseg
