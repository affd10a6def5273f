#include "server/receive_upload.h"

#include <fstream>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "meshseg/proto/sha256.h"

namespace meshseg::server {
namespace {

std::string Quote(const std::string& name) { return absl::StrCat("\"", name.substr(0, 128), "\""); }

}  // namespace

absl::Status CheckUploadHeader(const v1::UploadHeader& header, int64_t max_bytes) {
  if (header.file_name().empty()) {
    return absl::InvalidArgumentError("upload: header has no file_name");
  }
  const std::string name = Quote(header.file_name());
  if (header.total_size() <= 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "upload: ", name, ": total_size must be positive, got ", header.total_size()));
  }
  if (header.total_size() > max_bytes) {
    return absl::ResourceExhaustedError(absl::StrCat("upload: ", name, ": ",
                                                     header.total_size(),
                                                     " bytes exceed the limit of ", max_bytes));
  }
  if (!header.sha256().empty() && !IsSha256Hex(header.sha256())) {
    return absl::InvalidArgumentError(
        absl::StrCat("upload: ", name, ": sha256 must be 64 hex digits, got \"",
                     header.sha256().substr(0, 80), "\""));
  }
  return absl::OkStatus();
}

absl::Status ReceiveUpload(grpc::ServerContext* context,
                           grpc::ServerReaderInterface<v1::UploadRequest>* reader,
                           const v1::UploadHeader& header, int64_t max_bytes,
                           const std::string& path) {
  const std::string name = Quote(header.file_name());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return absl::InternalError(absl::StrCat("upload: cannot create spool file for ", name));

  Sha256 sha;
  int64_t received = 0;
  v1::UploadRequest request;
  while (reader->Read(&request)) {
    if (!request.has_chunk()) {
      return absl::InvalidArgumentError(
          absl::StrCat("upload: ", name, ": header sent again after ", received, " bytes"));
    }
    const std::string& chunk = request.chunk();
    received += static_cast<int64_t>(chunk.size());
    if (received > max_bytes) {
      return absl::ResourceExhaustedError(absl::StrCat(
          "upload: ", name, ": more than the limit of ", max_bytes, " bytes received"));
    }
    if (received > header.total_size()) {
      return absl::InvalidArgumentError(absl::StrCat("upload: ", name, ": ", received,
                                                     " bytes received, header declared ",
                                                     header.total_size()));
    }
    if (!out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()))) {
      return absl::InternalError(absl::StrCat("upload: ", name, ": spool write failed"));
    }
    sha.Update(chunk);
  }
  if (context->IsCancelled()) {
    return absl::CancelledError(absl::StrCat("upload: ", name, ": client went away after ",
                                             received, " bytes"));
  }
  if (received != header.total_size()) {
    return absl::InvalidArgumentError(absl::StrCat("upload: ", name, ": truncated, ", received,
                                                   " bytes received, header declared ",
                                                   header.total_size()));
  }
  if (!out.flush()) return absl::InternalError(absl::StrCat("upload: ", name, ": spool write failed"));
  if (!header.sha256().empty()) {
    const std::string digest = sha.HexDigest();
    if (digest != absl::AsciiStrToLower(header.sha256())) {
      return absl::InvalidArgumentError(absl::StrCat("upload: ", name, ": sha256 mismatch, header ",
                                                     header.sha256(), ", data ", digest));
    }
  }
  return absl::OkStatus();
}

}  // namespace meshseg::server
