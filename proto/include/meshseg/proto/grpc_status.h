// File: grpc_status.h
// -----------------------------------------------------------------------------
// absl::Status <-> grpc::Status. The codes are the same numbers in both; the
// message is cut at 1 KiB on the way out (as TF Serving does) so a long
// error never exceeds metadata limits.
#ifndef MESHSEG_PROTO_GRPC_STATUS_H_
#define MESHSEG_PROTO_GRPC_STATUS_H_

#include <cstddef>

#include <grpcpp/support/status.h>

#include "absl/status/status.h"

namespace meshseg {

// Longest error message sent to a client, in bytes.
inline constexpr std::size_t kMaxStatusMessageBytes = 1024;

// Returns `status` as a grpc::Status with the same code and its message cut
// at kMaxStatusMessageBytes.
grpc::Status ToGrpcStatus(const absl::Status& status);

// Returns `status` as an absl::Status with the same code and message.
absl::Status FromGrpcStatus(const grpc::Status& status);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_GRPC_STATUS_H_
