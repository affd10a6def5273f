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
  std::string format_hint = "";
  v1::SegmentOptions segment = {};
  // Bytes per chunk message.
  std::size_t chunk_bytes = std::size_t{1} << 20;
  // Send the file's SHA-256 for the server to check.
  bool checksum = true;
  // A headerless volume's layout: its raw_* fields are sent in the header.
  v1::UploadHeader raw = {};
  // UploadHeader.step / .step_unit: the server also writes the STEP file.
  bool step = false;
  std::string step_unit = "";
  // UploadHeader.request_id: a retry with the same id gets the same job.
  std::string request_id = "";
  // UploadHeader.include_mesh: the result carries the mesh its ids index.
  bool include_mesh = false;
  // UploadHeader.length_unit: the coordinates' unit, echoed in the result.
  std::string length_unit = "";
};

// How to reach a server that uses TLS or bearer tokens (server/credentials.h).
struct ConnectOptions {
  // PEM file of the CA that signed the server's certificate; set = TLS.
  std::string tls_ca = "";
  // PEM files of this client's certificate and key, for mutual TLS.
  std::string tls_cert = "";
  std::string tls_key = "";
  // Sent as "authorization: Bearer TOKEN" with every call; empty = none.
  std::string token = "";
};

class MeshsegClient {
 public:
  // `token`: sent with every call when not empty.
  explicit MeshsegClient(std::shared_ptr<grpc::Channel> channel, std::string token = "");

  // Returns a client of the server at `address` (HOST:PORT, plaintext).
  static MeshsegClient Connect(const std::string& address);

  // Returns a client of the server at `address` with TLS when
  // options.tls_ca is set and the bearer token if given.
  // Errors: NOT_FOUND for a PEM file that cannot be read; INVALID_ARGUMENT
  // for --tls-cert without --tls-key (or the reverse) or without --tls-ca.
  static absl::StatusOr<MeshsegClient> Connect(const std::string& address,
                                               const ConnectOptions& options);

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

  // Writes the STEP file of a SUCCEEDED job uploaded with `step` to `path`.
  // Errors: the server's NOT_FOUND when the job has none; INTERNAL when
  // `path` cannot be written.
  absl::Status SaveStep(const std::string& job_id, const std::string& path);

  absl::StatusOr<v1::Job> GetJob(const std::string& job_id);
  // Returns every job of the caller's tenant, oldest first (all pages).
  absl::StatusOr<std::vector<v1::Job>> ListJobs();
  // Returns one page of the caller's jobs (`request`: size, token, state).
  absl::StatusOr<v1::ListJobsResponse> ListJobsPage(const v1::ListJobsRequest& request);
  absl::StatusOr<v1::Job> Cancel(const std::string& job_id);

  // Upload, watch and fetch: the server path of `meshseg segment`. A job that
  // ends FAILED or CANCELLED returns its error code and message. `job`, when
  // given, receives the terminal job (its id and step_size).
  absl::StatusOr<v1::SegmentationResult> Segment(
      const std::string& path, const UploadOptions& options = {},
      const std::function<void(const v1::JobEvent&)>& on_event = {}, v1::Job* job = nullptr);

  v1::Segmentation::Stub& stub() { return *stub_; }

 private:
  // The bytes GetResult streams for `job_id` in `format`.
  absl::StatusOr<std::string> ResultBytes(const std::string& job_id, v1::ResultFormat format);

  // A context with the unary deadline set, authorized.
  std::unique_ptr<grpc::ClientContext> UnaryContext() const;
  // Adds the bearer token, if any, to `context`.
  void Authorize(grpc::ClientContext& context) const;

  std::unique_ptr<v1::Segmentation::Stub> stub_;
  std::string token_;
  absl::Duration call_timeout_ = absl::Seconds(30);
};

}  // namespace meshseg

#endif  // MESHSEG_CLIENT_MESHSEG_CLIENT_H_
