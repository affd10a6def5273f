// File: sha256.h
// -----------------------------------------------------------------------------
// The SHA-256 an upload may carry (UploadHeader.sha256): lowercase hex,
// computed incrementally over the chunks as they arrive or are sent.
#ifndef MESHSEG_PROTO_SHA256_H_
#define MESHSEG_PROTO_SHA256_H_

#include <memory>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"

namespace meshseg {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  // Adds `data` to the digest.
  void Update(std::string_view data);

  // Returns the digest of everything added, as 64 lowercase hex digits.
  // Call once.
  std::string HexDigest();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Returns the SHA-256 of the file at `path` in lowercase hex.
// Errors: NOT_FOUND if it cannot be opened; INTERNAL on a read error.
absl::StatusOr<std::string> FileSha256(const std::string& path);

// True if `hex` is 64 hex digits (either case).
bool IsSha256Hex(std::string_view hex);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SHA256_H_
