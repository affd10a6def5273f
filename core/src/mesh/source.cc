#include "mesh/source.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "absl/strings/str_cat.h"

namespace meshseg::mesh_internal {

std::string FileName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

absl::Status BadInput(const Source& src, std::string_view what) {
  return absl::InvalidArgumentError(
      absl::StrCat(std::string(src.op), ": \"", src.name, "\": ", std::string(what)));
}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  return *this;
}

FileBytes::~FileBytes() {
  if (data_ != nullptr) munmap(const_cast<char*>(data_), size_);
}

absl::StatusOr<FileBytes> ReadFileBytes(const std::string& path, const Source& src) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    return absl::NotFoundError(absl::StrCat(std::string(src.op), ": \"", src.name,
                                            "\": cannot open: ", std::strerror(errno)));
  }
  struct stat info;
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    close(fd);
    return BadInput(src, "not a regular file");
  }
  FileBytes bytes;
  if (info.st_size > 0) {
    void* map = mmap(nullptr, static_cast<size_t>(info.st_size), PROT_READ,
                     MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (map == MAP_FAILED) {
      close(fd);
      return BadInput(src, absl::StrCat("cannot map ", info.st_size, " bytes: ",
                                        std::strerror(errno)));
    }
    bytes.data_ = static_cast<const char*>(map);
    bytes.size_ = static_cast<size_t>(info.st_size);
  }
  close(fd);
  return bytes;
}

absl::Status CheckDeclaredCount(const Source& src, std::string_view what, int64_t count,
                                int64_t min_bytes, int64_t bytes_left, int64_t max_elements) {
  if (count < 0) return BadInput(src, absl::StrCat("negative ", std::string(what), " count ", count));
  if (count > max_elements) {
    return BadInput(src, absl::StrCat("header declares ", count, " ", std::string(what), ", over the limit of ",
                                      max_elements));
  }
  if (min_bytes > 0 && count > bytes_left / min_bytes) {
    return BadInput(src, absl::StrCat("header declares ", count, " ", std::string(what), " (at least ",
                                      min_bytes, " bytes each), but only ", bytes_left,
                                      " bytes follow"));
  }
  return absl::OkStatus();
}

}  // namespace meshseg::mesh_internal
