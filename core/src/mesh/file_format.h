// Recognising a file's format from its name and first bytes.
#ifndef MESHSEG_MESH_FILE_FORMAT_H_
#define MESHSEG_MESH_FILE_FORMAT_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

// Returns the format named by the extension of `path` (any case), else the
// one the content suggests: `head` is the start of the file (up to 4 KiB is
// enough), `size` the whole file size. kUnknown if neither tells.
FileFormat FormatOf(const std::string& path, std::string_view head, int64_t size);

// A file opened for reading: its mapped bytes (never empty) and its format
// (options.format if set, else FormatOf).
struct InputFile {
  FileBytes file;
  FileFormat format = FileFormat::kUnknown;
  std::string_view bytes() const { return file.view(); }
};

// Opens `path` for ReadMesh / ReadPointCloud. Errors: INVALID_ARGUMENT for a
// non-positive options.max_elements or an empty file; those of ReadFileBytes.
absl::StatusOr<InputFile> OpenInput(const std::string& path, const ReadMeshOptions& options,
                                    const Source& src);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_FILE_FORMAT_H_
