// File: grpc_status.h
// -----------------------------------------------------------------------------
// absl::Status <-> grpc::Status, and a Status into a Job's error fields. The
// codes are the same numbers in both; on the way out the message is made
// valid UTF-8 (utf8.h: it may quote bytes of an uploaded file) and cut at
// 1 KiB (as TF Serving does) so a long error never exceeds metadata limits.
#ifndef MESHSEG_PROTO_GRPC_STATUS_H_
#define MESHSEG_PROTO_GRPC_STATUS_H_

#include <cstddef>
#include <string>

#include <grpcpp/support/status.h>

#include "absl/status/status.h"
#include "meshseg/v1/service.pb.h"

namespace meshseg {

// Longest error message sent to a client, in bytes.
inline constexpr std::size_t kMaxStatusMessageBytes = 1024;

// Returns the message of `status` as sent to clients: control characters and
// bytes that are not UTF-8 escaped (EscapeToUtf8), then cut on a character
// boundary at kMaxStatusMessageBytes.
std::string WireMessage(const absl::Status& status);

// Returns `status` as a grpc::Status with the same code and WireMessage.
grpc::Status ToGrpcStatus(const absl::Status& status);

// Sets job->error_code and job->error_message from a non-OK `status`, the
// message as WireMessage: the one way a Status enters a Job.
void SetJobError(const absl::Status& status, v1::Job* job);

// Returns `status` as an absl::Status with the same code and message.
absl::Status FromGrpcStatus(const grpc::Status& status);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_GRPC_STATUS_H_
