#include "meshseg/proto/grpc_status.h"

#include <string>

#include "meshseg/proto/utf8.h"

namespace meshseg {

std::string WireMessage(const absl::Status& status) {
  std::string message =
      EscapeToUtf8(std::string_view(status.message().data(), status.message().size()));
  if (message.size() > kMaxStatusMessageBytes) {
    // Cut on a UTF-8 character boundary so the message stays valid text.
    std::size_t cut = kMaxStatusMessageBytes;
    while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) --cut;
    message.resize(cut);
  }
  return message;
}

grpc::Status ToGrpcStatus(const absl::Status& status) {
  if (status.ok()) return grpc::Status::OK;
  // absl::StatusCode and grpc::StatusCode share their numbers (both are
  // google.rpc.Code).
  return grpc::Status(static_cast<grpc::StatusCode>(status.code()), WireMessage(status));
}

void SetJobError(const absl::Status& status, v1::Job* job) {
  job->set_error_code(static_cast<int>(status.code()));
  job->set_error_message(WireMessage(status));
}

absl::Status FromGrpcStatus(const grpc::Status& status) {
  if (status.ok()) return absl::OkStatus();
  return absl::Status(static_cast<absl::StatusCode>(status.error_code()),
                      status.error_message());
}

}  // namespace meshseg
