// File: blob_store.h
// -----------------------------------------------------------------------------
// Where uploads and results live: a flat key -> bytes store that every
// replica reaches. Deliberately narrow (put, open, remove) so an object
// store can be added later without touching the job logic; the directory
// store (dir_blob_store.h) is the one built today, used on a local spool
// (embedded mode) or a shared volume (--blob-dir, Redis mode).
// Keys are "<job id>/<name>"; names never hold '/' or start with '.'.
#ifndef MESHSEG_SERVER_BLOB_STORE_H_
#define MESHSEG_SERVER_BLOB_STORE_H_

#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/statusor.h"

namespace meshseg::server {

// A blob readable as a local file for as long as this object lives (the
// pipeline reads paths). A remote store would download into a temp file and
// delete it in the destructor.
class LocalBlob {
 public:
  virtual ~LocalBlob() = default;
  virtual const std::string& path() const = 0;
  virtual int64_t size() const = 0;
};

class BlobStore {
 public:
  virtual ~BlobStore() = default;

  // Stores the finished local file at `local_path` under `key`, atomically
  // (readers see the whole blob or none) and durably (fsync'ed). The local
  // file is consumed. Errors: INTERNAL naming the key and the system error.
  virtual absl::Status Put(const std::string& key, const std::string& local_path) = 0;

  // Opens the blob `key`. Errors: NOT_FOUND if there is none.
  virtual absl::StatusOr<std::unique_ptr<LocalBlob>> Open(const std::string& key) const = 0;

  // Removes the blob `key`; OK if it was already gone.
  virtual absl::Status Remove(const std::string& key) = 0;
};

// The keys of a job's blobs.
std::string UploadKey(const std::string& job_id, const std::string& safe_file_name);
// A name no upload can take: SafeFileName never starts with '#'.
std::string ResultKey(const std::string& job_id);
// The job's STEP file (UploadHeader.step).
std::string StepKey(const std::string& job_id);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_BLOB_STORE_H_
