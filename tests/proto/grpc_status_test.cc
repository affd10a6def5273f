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

}  // namespace
}  // namespace meshseg
