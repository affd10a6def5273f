// File: spool.h
// -----------------------------------------------------------------------------
// The spool directory of one server process, the embedded mode's durable
// store: one folder per job holding its upload, its record (#record.pb,
// replaced atomically on every state change) and its result, so a restarted
// server recovers every accepted job. A lock file keeps a second server off
// the same spool (recovery would run its jobs twice). In Redis mode it is
// only the local scratch space for uploads and results in transit.
#ifndef MESHSEG_SERVER_SPOOL_H_
#define MESHSEG_SERVER_SPOOL_H_

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "server/dir_blob_store.h"
#include "server/job_record.pb.h"

namespace meshseg::server {

// JobRecord.format_version this server writes and reads.
inline constexpr int kRecordFormat = 1;

class Spool {
 public:
  // Opens the spool at `dir` (created if missing) and locks it.
  // Errors: FAILED_PRECONDITION if another server holds the lock; INTERNAL
  // if the directory cannot be created or locked.
  static absl::StatusOr<std::unique_ptr<Spool>> Open(const std::string& dir);
  ~Spool();
  Spool(const Spool&) = delete;
  Spool& operator=(const Spool&) = delete;

  // The job folders as a blob store (uploads and results).
  BlobStore& blobs() { return blobs_; }

  // A new local path for a file in transit (an upload being received, a
  // result being written) before it is Put into a blob store.
  std::string ScratchPath(const std::string& job_id, absl::string_view name) const;

  // Writes the record of record.job().job_id() atomically and durably.
  // Errors: INTERNAL naming the file.
  absl::Status WriteRecord(const JobRecord& record) const;

  // A job folder that could not be recovered, and why.
  struct Skipped {
    std::string folder;
    std::string reason;
  };
  struct Recovered {
    std::vector<JobRecord> records;  // in acceptance order
    std::vector<Skipped> skipped;
  };
  // Reads every job folder's record. A folder without a readable record of
  // a known format (left by an older or crashed server, or corrupt) is
  // skipped and reported, never deleted.
  Recovered Recover() const;

  // Removes the folder of `job_id` and everything in it (no error if
  // absent); symlinks in it are removed, not followed.
  void RemoveJob(const std::string& job_id) const;

  // Returns the number of uploads and results held (in job folders and in
  // transit); records are not counted.
  int64_t FileCount() const;

  const std::string& dir() const { return dir_; }

 private:
  Spool(std::string dir, int lock_fd);
  std::string dir_;
  int lock_fd_;
  DirBlobStore blobs_;
};

// Returns `file_name` without directories, with characters other than
// [A-Za-z0-9._-] replaced by '_', at most 100 bytes, never empty or hidden.
std::string SafeFileName(std::string_view file_name);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SPOOL_H_
