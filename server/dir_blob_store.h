// File: dir_blob_store.h
// -----------------------------------------------------------------------------
// BlobStore on a directory: key "a/b" is the file DIR/a/b. Put writes by
// rename (same file system) or copy into a temp file then rename, fsyncing
// the file and its folder, so a crash never leaves a half blob under a key.
// Removing a blob removes its folder once empty. Never follows symlinks
// when deleting.
#ifndef MESHSEG_SERVER_DIR_BLOB_STORE_H_
#define MESHSEG_SERVER_DIR_BLOB_STORE_H_

#include <string>

#include "server/blob_store.h"

namespace meshseg::server {

class DirBlobStore final : public BlobStore {
 public:
  // `dir` must exist (see Create()).
  explicit DirBlobStore(std::string dir) : dir_(std::move(dir)) {}

  // Returns the store at `dir`, created if missing.
  // Errors: INTERNAL if it cannot be created.
  static absl::StatusOr<std::unique_ptr<DirBlobStore>> Create(const std::string& dir);

  absl::Status Put(const std::string& key, const std::string& local_path) override;
  absl::StatusOr<std::unique_ptr<LocalBlob>> Open(const std::string& key) const override;
  absl::Status Remove(const std::string& key) override;

  const std::string& dir() const { return dir_; }

 private:
  std::string Path(const std::string& key) const;
  std::string dir_;
};

// Writes `bytes` to `path` atomically and durably: a temp file beside it,
// fsync, rename, fsync of the folder. Errors: INTERNAL naming the path.
absl::Status WriteFileAtomically(const std::string& path, const std::string& bytes);

// fsyncs the folder `dir` (so a rename in it survives a power loss).
absl::Status SyncDir(const std::string& dir);

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_DIR_BLOB_STORE_H_
