// File: meshseg_client.h
// -----------------------------------------------------------------------------
// A small C++ client of the meshseg.v1.Segmentation service: upload a file in
// 1 MiB chunks with its SHA-256, watch the job, fetch and parse the result,
// and the unary calls. Used by the `meshseg` CLI and the service tests.
// Every call returns absl::Status with the server's code and message.
#ifndef MESHSEG_CLIENT_MESHSEG_CLIENT_H_
#define MESHSEG_CLIENT_MESHSEG_CLIENT_H_

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <grpcpp/grpcpp.h>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "meshseg/v1/service.grpc.pb.h"

namespace meshseg {

struct UploadOptions {
  // Sent as UploadHeader.format_hint ("" = the server detects it).
  std::string format_hint;
  v1::SegmentOptions segment = {};
  // Bytes per chunk message.
  std::size_t chunk_bytes = std::size_t{1} << 20;
  // Send the file's SHA-256 for the server to check.
  bool checksum = true;
  // A headerless volume's layout: its raw_* fields are sent in the header.
  v1::UploadHeader raw;
};

class MeshsegClient {
 public:
  explicit MeshsegClient(std::shared_ptr<grpc::Channel> channel);

  // Returns a client of the server at `address` (HOST:PORT, plaintext).
  static MeshsegClient Connect(const std::string& address);

  // Deadline of the unary calls and of each call's wait for the connection.
  void set_call_timeout(absl::Duration timeout) { call_timeout_ = timeout; }

  // Uploads the file at `path`; returns the queued job.
  // Errors: NOT_FOUND if the file cannot be read; the server's status.
  absl::StatusOr<v1::UploadResponse> Upload(const std::string& path,
                                            const UploadOptions& options = {});

  // Watches `job_id` until it ends, calling `on_event` for each event;
  // returns the terminal job. `timeout` = InfiniteDuration() for none.
  absl::StatusOr<v1::Job> Watch(const std::string& job_id,
                                const std::function<void(const v1::JobEvent&)>& on_event = {},
                                absl::Duration timeout = absl::InfiniteDuration());

  // Returns the result of a SUCCEEDED job, reassembled from its chunks.
  absl::StatusOr<v1::SegmentationResult> Result(const std::string& job_id);

  absl::StatusOr<v1::Job> GetJob(const std::string& job_id);
  absl::StatusOr<std::vector<v1::Job>> ListJobs();
  absl::StatusOr<v1::Job> Cancel(const std::string& job_id);

  // Upload, watch and fetch: the server path of `meshseg segment`. A job that
  // ends FAILED or CANCELLED returns its error code and message.
  absl::StatusOr<v1::SegmentationResult> Segment(
      const std::string& path, const UploadOptions& options = {},
      const std::function<void(const v1::JobEvent&)>& on_event = {});

  v1::Segmentation::Stub& stub() { return *stub_; }

 private:
  // A context with the unary deadline set.
  std::unique_ptr<grpc::ClientContext> UnaryContext() const;

  std::unique_ptr<v1::Segmentation::Stub> stub_;
  absl::Duration call_timeout_ = absl::Seconds(30);
};

}  // namespace meshseg

#endif  // MESHSEG_CLIENT_MESHSEG_CLIENT_H_
