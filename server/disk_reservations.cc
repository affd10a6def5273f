#include "server/disk_reservations.h"

#include <sys/stat.h>
#include <sys/statvfs.h>

#include <cerrno>
#include <cstring>
#include <set>

#include "absl/strings/str_cat.h"

namespace meshseg::server {

DiskReservations::DiskReservations(std::vector<std::string> folders, int64_t min_free,
                                   FreeBytes free_bytes)
    : min_free_(min_free), free_bytes_(std::move(free_bytes)) {
  std::set<dev_t> devices;
  for (std::string& folder : folders) {
    struct stat info;
    // An unreadable folder is kept: Reserve() then reports it.
    if (stat(folder.c_str(), &info) == 0 && !devices.insert(info.st_dev).second) continue;
    folders_.push_back(std::move(folder));
  }
}

DiskReservations::Hold::~Hold() {
  absl::MutexLock lock(&owner_.mu_);
  owner_.reserved_ -= bytes_;
}

absl::StatusOr<int64_t> DiskReservations::StatvfsFreeBytes(const std::string& folder) {
  struct statvfs fs;
  if (statvfs(folder.c_str(), &fs) != 0) {
    return absl::InternalError(
        absl::StrCat("disk: cannot read free space of \"", folder, "\": ", std::strerror(errno)));
  }
  return static_cast<int64_t>(fs.f_bavail) * static_cast<int64_t>(fs.f_frsize);
}

absl::StatusOr<std::unique_ptr<DiskReservations::Hold>> DiskReservations::Reserve(int64_t bytes) {
  absl::MutexLock lock(&mu_);
  for (const std::string& folder : folders_) {
    const absl::StatusOr<int64_t> free = free_bytes_(folder);
    if (!free.ok()) return free.status();
    // Uploads in flight have not written their bytes yet: count them.
    if (*free - reserved_ - bytes < min_free_) {
      return absl::ResourceExhaustedError(absl::StrCat(
          "upload: ", bytes, " bytes do not fit on the disk of \"", folder, "\": ", *free,
          " bytes free, ", reserved_, " reserved by uploads in flight, ", min_free_,
          " kept free (--min-free-disk)"));
    }
  }
  reserved_ += bytes;
  return std::unique_ptr<Hold>(new Hold(*this, bytes));
}

int64_t DiskReservations::reserved() const {
  absl::MutexLock lock(&mu_);
  return reserved_;
}

}  // namespace meshseg::server
