#include "mesh/source.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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

absl::StatusOr<std::string> ReadFileBytes(const std::string& path, const Source& src) {
  struct stat info;
  if (stat(path.c_str(), &info) != 0) {
    return absl::NotFoundError(
        absl::StrCat(std::string(src.op), ": \"", src.name, "\": cannot open: ", std::strerror(errno)));
  }
  if (!S_ISREG(info.st_mode)) return BadInput(src, "not a regular file");
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (file == nullptr) {
    return absl::NotFoundError(
        absl::StrCat(std::string(src.op), ": \"", src.name, "\": cannot open: ", std::strerror(errno)));
  }
  std::string bytes(static_cast<size_t>(info.st_size), '\0');
  const size_t got = std::fread(bytes.data(), 1, bytes.size(), file.get());
  if (got != bytes.size()) {
    return BadInput(src, absl::StrCat("read ", got, " of ", bytes.size(), " bytes"));
  }
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
