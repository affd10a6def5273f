// Helpers shared by the readers of the mesh stage: the file being read, its
// bytes, and the INVALID_ARGUMENT messages that name it.
#ifndef MESHSEG_MESH_SOURCE_H_
#define MESHSEG_MESH_SOURCE_H_

#include <string>
#include <string_view>
#include <utility>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace meshseg::mesh_internal {

// The operation and file a reader works on, for messages.
struct Source {
  std::string_view op;  // "read_mesh", "read_point_cloud"
  std::string name;     // file name without directories
};

// Returns "bracket.stl" for "/a/b/bracket.stl".
std::string FileName(const std::string& path);

// Returns INVALID_ARGUMENT `<op>: "<name>": <what>`.
absl::Status BadInput(const Source& src, std::string_view what);

// The whole content of a file, mapped read-only (no copy, no zero-fill).
class FileBytes {
 public:
  FileBytes() = default;
  FileBytes(FileBytes&& other) noexcept { *this = std::move(other); }
  FileBytes& operator=(FileBytes&& other) noexcept;
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  ~FileBytes();

  std::string_view view() const { return {data_, size_}; }

 private:
  friend absl::StatusOr<FileBytes> ReadFileBytes(const std::string& path, const Source& src);
  const char* data_ = nullptr;
  size_t size_ = 0;
};

// Returns the whole content of `path`.
// Errors: NOT_FOUND if it cannot be opened; INVALID_ARGUMENT if it is not a
// regular file or cannot be mapped.
absl::StatusOr<FileBytes> ReadFileBytes(const std::string& path, const Source& src);

// Returns OK if `count` elements of at least `min_bytes` each can fit in
// `bytes_left` bytes and `count` <= `max_elements`; else an error naming
// `what` ("vertices", "faces", "triangles", "points") and the limit. Readers
// call it before reserving memory for a declared count.
absl::Status CheckDeclaredCount(const Source& src, std::string_view what, int64_t count,
                                int64_t min_bytes, int64_t bytes_left, int64_t max_elements);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_SOURCE_H_
