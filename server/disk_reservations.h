// File: disk_reservations.h
// -----------------------------------------------------------------------------
// Free disk space reserved for uploads before their data is accepted. An
// upload lands in the scratch folder and is then put in the blob store
// (the same filesystem in the embedded mode; a shared volume in the Redis
// mode), so its declared size is reserved on every filesystem it will
// occupy. A reservation is refused when the filesystem's free space, less
// what uploads in flight have reserved, would drop under the floor kept
// free for results and records (--min-free-disk). Released when the upload
// ends (its file is then on disk, or removed). Thread-safe.
#ifndef MESHSEG_SERVER_DISK_RESERVATIONS_H_
#define MESHSEG_SERVER_DISK_RESERVATIONS_H_

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"

namespace meshseg::server {

class DiskReservations {
 public:
  // Free bytes of the filesystem holding a folder (statvfs f_bavail), or an
  // error; replaceable for tests.
  using FreeBytes = std::function<absl::StatusOr<int64_t>(const std::string& folder)>;

  // `folders`: where an upload's bytes go (duplicates on one filesystem are
  // counted once). `min_free`: bytes each filesystem keeps free.
  DiskReservations(std::vector<std::string> folders, int64_t min_free,
                   FreeBytes free_bytes = StatvfsFreeBytes);

  // A held reservation, given back on destruction.
  class Hold {
   public:
    ~Hold();
    Hold(const Hold&) = delete;
    Hold& operator=(const Hold&) = delete;

   private:
    friend class DiskReservations;
    Hold(DiskReservations& owner, int64_t bytes) : owner_(owner), bytes_(bytes) {}
    DiskReservations& owner_;
    const int64_t bytes_;
  };

  // Reserves `bytes` on every filesystem. Errors: RESOURCE_EXHAUSTED naming
  // the folder, its free bytes, what is reserved and the floor; INTERNAL if
  // free space cannot be read.
  absl::StatusOr<std::unique_ptr<Hold>> Reserve(int64_t bytes);

  // Bytes reserved by uploads in flight.
  int64_t reserved() const;

  static absl::StatusOr<int64_t> StatvfsFreeBytes(const std::string& folder);

 private:
  std::vector<std::string> folders_;  // one per filesystem
  const int64_t min_free_;
  const FreeBytes free_bytes_;
  mutable absl::Mutex mu_;
  int64_t reserved_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_DISK_RESERVATIONS_H_
