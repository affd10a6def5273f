// File: receive_upload.h
// -----------------------------------------------------------------------------
// The body of an Upload stream: the chunks after the header, written to the
// spool file as they arrive (never held in memory whole) and checked against
// the header's size and checksum and the server's size limit.
#ifndef MESHSEG_SERVER_RECEIVE_UPLOAD_H_
#define MESHSEG_SERVER_RECEIVE_UPLOAD_H_

#include <cstdint>
#include <string>

#include <grpcpp/grpcpp.h>
#include <grpcpp/support/sync_stream.h>

#include "absl/status/status.h"
#include "meshseg/v1/service.pb.h"

namespace meshseg::server {

// Returns OK if `header` may start an upload on a server that accepts at
// most `max_bytes`.
// Errors: INVALID_ARGUMENT (no file name, total_size <= 0, a checksum that is
// not 64 hex digits); RESOURCE_EXHAUSTED (total_size over max_bytes).
absl::Status CheckUploadHeader(const v1::UploadHeader& header, int64_t max_bytes);

// Reads the chunks that follow `header` from `reader` into a new file at
// `path`. Errors: INVALID_ARGUMENT (a second header, more or fewer bytes
// than total_size, checksum mismatch); RESOURCE_EXHAUSTED (over max_bytes);
// CANCELLED (the client went away or its deadline passed); INTERNAL (the
// spool file cannot be written). On error the file may exist; the caller
// removes it.
absl::Status ReceiveUpload(grpc::ServerContext* context,
                           grpc::ServerReaderInterface<v1::UploadRequest>* reader,
                           const v1::UploadHeader& header, int64_t max_bytes,
                           const std::string& path);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_RECEIVE_UPLOAD_H_
