// File: spool.h
// -----------------------------------------------------------------------------
// The spool directory: one folder per job holding its upload while it waits
// and runs, then its serialized result until the result expires. Nothing is
// kept in memory twice; a failed or cancelled job leaves no file behind.
#ifndef MESHSEG_SERVER_SPOOL_H_
#define MESHSEG_SERVER_SPOOL_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"

namespace meshseg::server {

class Spool {
 public:
  // Returns the spool at `dir`, created if missing. Job folders a previous
  // run left behind (names starting with "job-") are removed.
  // Errors: INTERNAL if the directory cannot be created or listed.
  static absl::StatusOr<Spool> Open(const std::string& dir);

  // Creates the folder of `job_id` and returns the path its upload goes to:
  // the base name of `file_name` with unsafe characters replaced.
  // Errors: INTERNAL if the folder cannot be created.
  absl::StatusOr<std::string> CreateJob(const std::string& job_id,
                                        std::string_view file_name) const;

  // Returns the path of the serialized SegmentationResult of `job_id`.
  std::string ResultPath(const std::string& job_id) const;

  // Removes the folder of `job_id` and everything in it (no error if absent).
  void RemoveJob(const std::string& job_id) const;

  // Returns the number of regular files in the spool (all job folders).
  int64_t FileCount() const;

  const std::string& dir() const { return dir_; }

 private:
  explicit Spool(std::string dir) : dir_(std::move(dir)) {}
  std::string JobDir(const std::string& job_id) const;

  std::string dir_;
};

// Returns `file_name` without directories, with characters other than
// [A-Za-z0-9._-] replaced by '_', at most 100 bytes, never empty or hidden.
std::string SafeFileName(std::string_view file_name);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_SPOOL_H_
